// One meshing run as the command line does it, shared by the CLI and the
// Python module: generate_mesh on a loaded input with the resolved criteria,
// the quality measures and the fidelity check, and the JSON report. Writing
// the mesh, exit codes and printing stay with the caller.
#pragma once

#include <exception>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "rdmesh/atomic_file.h"
#include "rdmesh/criteria.h"
#include "rdmesh/fem_options.h"
#include "rdmesh/fidelity.h"
#include "rdmesh/mesher.h"
#include "rdmesh/quality_report.h"
#include "rdmesh/run_setup.h"

namespace rdmesh::run {

/// The mesh file written on a second thread while the mesh was checked
/// (mesh_loaded), waiting under its temporary name for write_outputs.
struct StagedMesh {
  std::optional<StagedFile> file;
  std::exception_ptr error;  ///< what writing it threw, rethrown only if it is wanted
  double seconds = 0;        ///< the staging thread's time, counted as write time
  bool started() const { return file || error; }
};

struct MeshRun {
  Criteria criteria;
  MeshResult result;
  QualityReport quality;
  std::optional<FidelityReport> fidelity;  ///< CAD models and triangle meshes only
  RunTimes times;                          ///< `write` is the caller's to fill in
  FemResults fem;  ///< the caller's apply_fem_options, before writing (none on a failed run)
  /// opt.output, written while the mesh was checked (on more than one thread,
  /// when no FEM option changes the mesh): write_outputs commits or drops it.
  StagedMesh staged;

  /// The time limit stopped refinement, the mesh has inverted or flat
  /// tetrahedra (whatever the input: no solver takes them), or it failed the
  /// fidelity check.
  bool failed() const {
    return result.stats.time_limit_reached || quality.inverted_tets > 0 ||
           (fidelity && !fidelity->passed);
  }
};

/// Meshes `input` with `criteria` (resolve_criteria) and `base`'s progress
/// callback; the other MeshOptions come from `opt` (features, surface only,
/// exudation, time limit). Measures every distance when opt.full_check or a
/// report is asked for, then checks fidelity (model_measures), announced to the
/// callback as the phase "checking the mesh against the model". On more than
/// one thread the mesh file is written meanwhile (MeshRun::staged). Throws
/// what generate_mesh throws; a failed check is not an exception (MeshRun::failed).
MeshRun mesh_loaded(const Options& opt, const LoadedInput& input, const Criteria& criteria,
                    MeshOptions base = {});

/// The one-line reason of a failed run (time limit, inverted tetrahedra or
/// fidelity), without the input's name: "the mesh does not match the model:
/// ..."; empty when the run did not fail.
std::string failure_reason(const Options& opt, const MeshRun& run);

/// The JSON report of a run (what --report writes) on `oracle`, the input's.
nlohmann::json run_report(const Options& opt, const DomainOracle& oracle, const MeshRun& run);

/// apply_fem_options on the run's mesh (second order, partitions; the sizes
/// asked measured), announced to `options.progress`; fills run.fem.
void apply_fem(const Options& opt, const AppliedSizes& sizes, const DomainOracle& oracle,
               const MeshOptions& options, MeshRun& run);

/// What `opt` asks to write, as the command does, each announced as a phase:
/// with `write_mesh_too` the mesh (opt.output, opt.write) and the picture, then
/// the report (always, when asked: a failed run's report says why). Sets
/// run.times.write (mesh and picture). Empty paths are skipped. A staged mesh
/// file is committed, or dropped without `write_mesh_too`.
void write_outputs(const Options& opt, const DomainOracle& oracle, const MeshOptions& options,
                   bool write_mesh_too, MeshRun& run);

/// Tells `options.progress` (if any) that `phase` starts: a Progress with that
/// phase and zero counts, as the mesher announces its own phases.
void announce(const MeshOptions& options, const std::string& phase);

}  // namespace rdmesh::run
