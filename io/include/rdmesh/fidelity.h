// The fidelity check: does the mesh match the model it was made from?
//
// A run that ends with a mesh missing part of the model must not report
// success. After meshing a CAD model or a triangle mesh, whose exact volumes
// and areas are known, the mesh is compared with the model:
//   - every patch of the model has triangles in the mesh, except a sliver face
//     all of whose curves are below the minimum size (next item): listed;
//   - every curve is one chain of feature edges (QualityReport's is_chain),
//     except curves closer to another feature than the run's minimum size (the
//     protection could not separate them: RefinementStats::curves_below_min_size),
//     which the run warned about; they are listed, not failed;
//   - the volume of each subdomain is the model's within a tolerance derived
//     from the criteria: a boundary that stays within the facet distance d of
//     the true surface encloses a volume within d x area of the surfaces
//     around the subdomain, so the tolerance is the sum over the subdomain's
//     patches of d x area (the model's area when known, else the mesh's; d
//     the facet distance averaged over the patch's triangles, as it may vary:
//     near slender CAD parts it follows their thickness), plus 1e-9 of the
//     volume for rounding. Whatever the criteria, the tolerance is at most
//     kMaxVolumeDeviation (10%) of the volume: a facet distance larger than
//     the part is thick allows any loss, and a mesh that lost a tenth of a
//     solid does not match it, whatever was asked. (A mesh whose boundary
//     follows its surfaces to d passes; one that lost a piece of the model, or
//     whose labels leaked, does not.)
// Subdomains whose model volume is unknown are checked as a whole when the
// model's total volume is known (triangle meshes).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "rdmesh/oracle.h"
#include "rdmesh/quality_report.h"

namespace rdmesh {

/// The largest relative volume deviation check_fidelity accepts, whatever the
/// facet distance (see the file comment).
inline constexpr double kMaxVolumeDeviation = 0.1;

/// Exact measures of the model (from OpenCASCADE's BRepGProp for CAD models,
/// from the input triangles for triangle meshes).
struct ModelMeasures {
  /// Volume of each subdomain, index = id - 1; empty when unknown.
  std::vector<double> subdomain_volume;
  /// Volume of the whole domain, when subdomain_volume is empty.
  std::optional<double> total_volume;
  /// Area of each patch, index = id - 1 (the oracle's patch ids); empty: the
  /// mesh's own patch areas serve (a lost piece of surface then only makes the
  /// tolerance smaller).
  std::vector<double> patch_area;
};

/// One subdomain's (or the whole domain's, id 0) volume against the model's.
struct VolumeCheck {
  SubdomainId id;
  std::string name;
  double mesh_volume = 0;
  double model_volume = 0;
  double tolerance = 0;  ///< allowed |mesh - model|
  bool passed = true;
};

struct FidelityReport {
  bool passed = true;
  std::vector<VolumeCheck> volumes;
  std::vector<PatchId> missing_patches;  ///< patches of the model without triangles
  std::vector<CurveId> broken_curves;    ///< curves that are not one chain of edges
  /// Curves below the minimum size that are not one chain: not a failure.
  std::vector<CurveId> unresolved_curves;
  /// Patches without triangles all of whose curves are below the minimum size:
  /// not a failure.
  std::vector<PatchId> unresolved_patches;
  /// One short phrase per problem, e.g. "solid_1: volume 1.466e+06, model 5.215e+06
  /// (-71.9%, allowed +-3.1%)"; empty when passed.
  std::vector<std::string> problems;
};

/// Compares the measured mesh (`quality`, from measure_quality; distances need
/// not be measured) with `model`. `patches` and `curves` are the oracle's;
/// `facet_distance` the criteria's; `below_min_size` the curves the run could
/// not separate from other features (RefinementStats::curves_below_min_size).
/// `patch_facet_distance[k]` is the facet distance on patch k + 1
/// (patch_facet_distances); a patch past its end gets its largest value.
FidelityReport check_fidelity(const QualityReport& quality, const ModelMeasures& model,
                              const std::vector<PatchInfo>& patches,
                              const std::vector<CurveInfo>& curves,
                              const std::vector<double>& patch_facet_distance,
                              const std::vector<CurveId>& below_min_size = {});
/// The same with one facet distance for every patch.
FidelityReport check_fidelity(const QualityReport& quality, const ModelMeasures& model,
                              const std::vector<PatchInfo>& patches,
                              const std::vector<CurveInfo>& curves, double facet_distance,
                              const std::vector<CurveId>& below_min_size = {});

/// The facet distance `d` averaged (by area) over each patch's boundary
/// triangles of `mesh`, at their centroids; index = patch id - 1. A patch
/// without triangles gets the largest value.
std::vector<double> patch_facet_distances(const TetMesh& mesh, const ScalarField& d);

/// The report as JSON: passed, volumes (id, name, mesh, model, tolerance,
/// passed), missing_patches, broken_curves (ids) and problems.
nlohmann::json to_json(const FidelityReport& r);

/// One line for the user: the first few problems and how many there are.
std::string summarize_problems(const FidelityReport& report);

}  // namespace rdmesh
