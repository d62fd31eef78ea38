// The CLI's FEM options (--order, --partitions) and what they add to the
// summary and the JSON report. Applied to the mesh after the fidelity check,
// before writing.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "rdmesh/oracle.h"
#include "rdmesh/partition.h"
#include "rdmesh/second_order.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh::cli {

struct FemOptions {
  int order = 1;       ///< --order 1|2: 2 = 10-node tetrahedra on the exact geometry
  int partitions = 0;  ///< --partitions N: METIS on the dual graph, 0 = none
};

void add_fem_options(CLI::App& app, FemOptions& opt);

/// Before meshing: refuses (InputError) what the options cannot give:
/// partitions of a surface-only mesh, partitions in a Medit file.
void check_fem_options(const FemOptions& opt, const std::string& input, const std::string& output,
                       bool surface_only);

struct FemResults {
  std::optional<SecondOrderStats> second_order;
  std::optional<PartitionStats> partitions;
};

/// Turns `mesh` into what the options ask for (second order, then partitions).
FemResults apply_fem_options(const FemOptions& opt, TetMesh& mesh, const DomainOracle& oracle);

/// The report's "second_order" and "partitions" entries (null when not asked).
nlohmann::json fem_json(const FemResults& results);

/// Summary lines (empty when no FEM option was used).
std::string format_fem_summary(const FemResults& results);

}  // namespace rdmesh::cli
