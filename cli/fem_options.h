// The CLI's FEM options (--order) and what they add to the summary and the
// JSON report. Applied to the mesh after the fidelity check, before writing.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "rdmesh/oracle.h"
#include "rdmesh/second_order.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh::cli {

struct FemOptions {
  int order = 1;  ///< --order 1|2: 2 = 10-node tetrahedra on the exact geometry
};

void add_fem_options(CLI::App& app, FemOptions& opt);

struct FemResults {
  std::optional<SecondOrderStats> second_order;
};

/// Turns `mesh` into what the options ask for (second order).
FemResults apply_fem_options(const FemOptions& opt, TetMesh& mesh, const DomainOracle& oracle);

/// The report's "second_order" entry (null for a first-order mesh).
nlohmann::json fem_json(const FemResults& results);

/// Summary lines (empty when no FEM option was used).
std::string format_fem_summary(const FemResults& results);

}  // namespace rdmesh::cli
