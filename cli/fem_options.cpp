#include "fem_options.h"

#include <sstream>

#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"

namespace rdmesh::cli {

void add_fem_options(CLI::App& app, FemOptions& opt) {
  app.add_option("--order", opt.order,
                 "Element order: 1 (4-node tetrahedra) or 2 (10-node tetrahedra, 6-node "
                 "triangles, 3-node curve edges; boundary mid-edge nodes on the exact surfaces "
                 "and curves)")
      ->check(CLI::IsMember({1, 2}));
  app.add_option("--partitions", opt.partitions,
                 "Split the tetrahedra into N partitions (METIS on the dual graph): .msh "
                 "partitioned entities, a 'partition' cell array in .vtu")
      ->check(CLI::Range(1, 1 << 20));
}

void check_fem_options(const FemOptions& opt, const std::string& input, const std::string& output,
                       bool surface_only) {
  if (opt.partitions == 0) return;
  if (surface_only) {
    throw InputError(input, "--partitions needs tetrahedra: it cannot go with --surface-only");
  }
  if (format_from_path(output) == MeshFormat::Medit) {
    throw InputError(output,
                     "a Medit file cannot carry partitions (--partitions): write .msh or .vtu");
  }
}

FemResults apply_fem_options(const FemOptions& opt, TetMesh& mesh, const DomainOracle& oracle) {
  FemResults r;
  if (opt.order == 2) r.second_order = make_second_order(mesh, oracle);
  if (opt.partitions > 0) r.partitions = partition_mesh(mesh, opt.partitions);
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
  if (const auto& p = results.partitions) {
    j["partitions"] = {{"parts", p->parts},
                       {"edge_cut", p->edge_cut},
                       {"dual_edges", p->dual_edges},
                       {"imbalance", p->imbalance},
                       {"tets_per_part", p->tets_per_part},
                       {"seconds", p->seconds}};
  } else {
    j["partitions"] = nullptr;
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
  if (const auto& p = results.partitions) {
    s << "partitions: " << p->parts << " (METIS), edge cut " << p->edge_cut << " of "
      << p->dual_edges << " shared faces, largest " << p->imbalance << " x the average, "
      << p->seconds << " s\n";
  }
  return s.str();
}

}  // namespace rdmesh::cli
