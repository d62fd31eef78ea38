// The CLI's FEM options (--order, --partitions) and what they add to the
// summary and the JSON report. Applied to the mesh after the fidelity check,
// before writing.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "rdmesh/criteria.h"
#include "rdmesh/entity_sizes.h"
#include "rdmesh/oracle.h"
#include "rdmesh/partition.h"
#include "rdmesh/second_order.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh::run {

struct FemOptions {
  int order = 1;                     ///< --order 1|2: 2 = 10-node tetrahedra on the exact geometry
  int partitions = 0;                ///< --partitions N: METIS on the dual graph, 0 = none
  std::vector<std::string> size_on;  ///< --size-on KIND:WHICH=SIZE (repeatable)
  std::string sizes_file;            ///< --sizes FILE.json: {"KIND:WHICH": SIZE, "grade": G}
  std::optional<double> grade;       ///< --grade G (default: the file's, else 1.4)
  std::optional<double> curvature;  ///< --curvature N: elements per full turn (default: the file's)
};

void add_fem_options(CLI::App& app, FemOptions& opt);

/// Before meshing: refuses (InputError) what the options cannot give:
/// partitions of a surface-only mesh, partitions in a Medit file or in MSH 2.2
/// (`msh22`: its writer has no partitioned entities) (`output` empty: no file yet).
void check_fem_options(const FemOptions& opt, const std::string& input, const std::string& output,
                       bool surface_only, bool msh22 = false);

/// The sizes asked and what applying them found.
struct AppliedSizes {
  SizeRequests requests;
  SizesApplied applied;
};

/// Reads --size-on, the domain file's "sizes" (`from_domain`), --sizes,
/// --grade and --curvature (entities from all; the later ones override the
/// grade and curvature), lowers `criteria` accordingly (entity_sizes.h). Throws
/// InputError for a bad entity, size, grade, curvature or sizes file.
AppliedSizes apply_size_options(const FemOptions& opt, const std::optional<SizeSpec>& from_domain,
                                const DomainOracle& oracle, Criteria& criteria);

struct FemResults {
  std::vector<AchievedSize> sizes;  ///< per entity of --size-on / --sizes
  double grade = 0;
  double sizing_seconds = 0;  ///< sampling entities and curvatures before meshing
  std::optional<CurvatureStats> curvature;
  std::optional<CurvatureAchieved> curvature_achieved;
  std::optional<SecondOrderStats> second_order;
  std::optional<PartitionStats> partitions;
};

/// Measures the sizes asked, then turns `mesh` into what the options ask for
/// (second order, then partitions).
FemResults apply_fem_options(const FemOptions& opt, const AppliedSizes& sizes, TetMesh& mesh,
                             const DomainOracle& oracle, double min_size);

/// The report's "entity_sizes", "curvature_sizes", "second_order" and "partitions" entries
/// (null when not asked).
nlohmann::json fem_json(const FemResults& results);

/// Summary lines (empty when no FEM option was used).
std::string format_fem_summary(const FemResults& results);

}  // namespace rdmesh::run
