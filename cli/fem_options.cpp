#include "fem_options.h"

#include <sstream>

namespace rdmesh::cli {

void add_fem_options(CLI::App& app, FemOptions& opt) {
  app.add_option("--order", opt.order,
                 "Element order: 1 (4-node tetrahedra) or 2 (10-node tetrahedra, 6-node "
                 "triangles, 3-node curve edges; boundary mid-edge nodes on the exact surfaces "
                 "and curves)")
      ->check(CLI::IsMember({1, 2}));
}

FemResults apply_fem_options(const FemOptions& opt, TetMesh& mesh, const DomainOracle& oracle) {
  FemResults r;
  if (opt.order == 2) r.second_order = make_second_order(mesh, oracle);
  return r;
}

nlohmann::json fem_json(const FemResults& results) {
  nlohmann::json j = nlohmann::json::object();
  if (const auto& s = results.second_order) {
    j["second_order"] = {{"mid_nodes", s->mid_nodes},
                         {"curve_nodes", s->curve_nodes},
                         {"surface_nodes", s->surface_nodes},
                         {"straightened", s->straightened},
                         {"placement_failures", s->placement_failures},
                         {"min_scaled_jacobian", s->min_scaled_jacobian},
                         {"max_relative_offset", s->max_relative_offset},
                         {"seconds", s->seconds}};
  } else {
    j["second_order"] = nullptr;
  }
  return j;
}

std::string format_fem_summary(const FemResults& results) {
  std::ostringstream s;
  if (const auto& r = results.second_order) {
    s << "second order: " << r->mid_nodes << " mid-edge nodes (" << r->curve_nodes << " on curves, "
      << r->surface_nodes << " on patches), " << r->straightened
      << " straightened to keep Jacobians positive, " << r->placement_failures
      << " left on the chord (projection failed); min scaled Jacobian " << r->min_scaled_jacobian
      << ", " << r->seconds << " s\n";
  }
  return s.str();
}

}  // namespace rdmesh::cli
