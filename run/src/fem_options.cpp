#include "rdmesh/fem_options.h"

#include <fstream>
#include <sstream>

#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"

namespace rdmesh::run {

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
  app.add_option("--size-on", opt.size_on,
                 "Size on or in one entity, KIND:WHICH=SIZE with KIND face, curve or solid and "
                 "WHICH its id or name, e.g. face:12=0.5 (repeatable; graded by --grade)");
  app.add_option(
      "--sizes", opt.sizes_file,
      "JSON file of entity sizes: {\"face:12\": 0.5, \"curve:rim\": 0.1, \"grade\": 1.3}");
  app.add_option("--curvature", opt.curvature,
                 "At least N elements per full turn on curved faces and curves (Gmsh's -clcurv): "
                 "size pi R / N where the radius of curvature is R, graded by --grade")
      ->check(CLI::PositiveNumber);
  app.add_option("--grade", opt.grade,
                 "Entity and curvature sizes grow by at most this factor from one element to the "
                 "next (> 1; default 1.4)");
}

AppliedSizes apply_size_options(const FemOptions& opt, const std::optional<SizeSpec>& from_domain,
                                const DomainOracle& oracle, Criteria& criteria) {
  AppliedSizes out;
  // --size-on first, then the domain file's, then the sizing file's; an
  // entity a file names but the domain lacks is that file's error.
  for (const std::string& s : opt.size_on)
    out.requests.entities.push_back(parse_entity_size(s, oracle));
  SizeSpec spec;
  if (from_domain) {
    spec = *from_domain;
    try {
      (void)resolve_size_spec(spec, oracle);
    } catch (const InputError& e) {
      throw InputError("the domain file's 'sizes': " + std::string(e.what()));
    }
  }
  if (!opt.sizes_file.empty()) {
    const SizeSpec file = read_size_spec(opt.sizes_file);
    try {
      (void)resolve_size_spec(file, oracle);
    } catch (const InputError& e) {
      throw InputError(opt.sizes_file, e.what());
    }
    merge_size_spec(spec, file);
  }
  const SizeRequests files = resolve_size_spec(spec, oracle);
  out.requests.entities.insert(out.requests.entities.end(), files.entities.begin(),
                               files.entities.end());
  out.requests.grade = files.grade;
  out.requests.curvature = files.curvature;
  if (opt.grade) out.requests.grade = *opt.grade;
  if (opt.curvature) out.requests.curvature = *opt.curvature;
  out.applied = apply_sizes(oracle, out.requests, criteria);
  return out;
}

void check_fem_options(const FemOptions& opt, const std::string& input, const std::string& output,
                       bool surface_only, bool msh22) {
  if (opt.partitions == 0) return;
  if (surface_only) {
    throw InputError(input, "--partitions needs tetrahedra: it cannot go with --surface-only");
  }
  if (!output.empty() && format_from_path(output) == MeshFormat::Medit) {
    throw InputError(output,
                     "a Medit file cannot carry partitions (--partitions): write .msh or .vtu");
  }
  if (!output.empty() && msh22 && format_from_path(output) == MeshFormat::Gmsh41) {
    throw InputError(output,
                     "rdmesh writes no partitions (--partitions) in MSH 2.2 (--format msh22): "
                     "write MSH 4.1 (the default) or .vtu");
  }
}

FemResults apply_fem_options(const FemOptions& opt, const AppliedSizes& sizes, TetMesh& mesh,
                             const DomainOracle& oracle, double min_size) {
  FemResults r;
  r.sizes = achieved_sizes(mesh, sizes.requests.entities);
  r.grade = sizes.requests.grade;
  r.sizing_seconds = sizes.applied.seconds;
  if (sizes.requests.curvature > 0) {
    r.curvature = sizes.applied.curvature;
    r.curvature_achieved = achieved_curvature(mesh, oracle, sizes.requests.curvature, min_size);
  }
  if (opt.order == 2) r.second_order = make_second_order(mesh, oracle);
  if (opt.partitions > 0) r.partitions = partition_mesh(mesh, opt.partitions);
  return r;
}

nlohmann::json fem_json(const FemResults& results) {
  nlohmann::json j = nlohmann::json::object();
  j["entity_sizes"] = nullptr;
  if (!results.sizes.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const AchievedSize& a : results.sizes) {
      list.push_back({{"entity", a.asked.label},
                      {"id", a.asked.id},
                      {"requested", a.asked.size},
                      {"edges", a.edges},
                      {"mean_edge", a.mean_edge},
                      {"max_edge", a.max_edge}});
    }
    j["entity_sizes"] = list;
  }
  j["curvature_sizes"] = nullptr;
  if (const auto& c = results.curvature) {
    const CurvatureAchieved& a = *results.curvature_achieved;
    j["curvature_sizes"] = {{"per_turn", c->per_turn},
                            {"samples", c->samples},
                            {"unknown", c->unknown},
                            {"clamped_to_min_size", c->clamped},
                            {"pieces", c->pieces},
                            {"min_radius", c->min_radius},
                            {"min_size", c->min_size},
                            {"curve_edges", a.curve_edges},
                            {"curve_edges_over", a.curve_over},
                            {"curve_max_ratio", a.curve_max_ratio},
                            {"facets", a.facets},
                            {"facets_over", a.facets_over},
                            {"facet_max_ratio", a.facet_max_ratio},
                            {"facet_mean_ratio", a.facet_mean_ratio}};
  }
  if (!results.sizes.empty() || results.curvature) j["sizing_seconds"] = results.sizing_seconds;
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
  for (const AchievedSize& a : results.sizes) {
    s << "size on " << a.asked.label << ": asked " << a.asked.size << ", edges mean " << a.mean_edge
      << ", max " << a.max_edge << " (" << a.edges << " edges)\n";
  }
  if (const auto& c = results.curvature) {
    const CurvatureAchieved& a = *results.curvature_achieved;
    s << "curvature sizes: " << c->per_turn << " per turn, " << c->samples << " samples ("
      << c->clamped << " clamped to the minimum size, " << c->unknown
      << " unknown), radius >= " << c->min_radius << "; longest edge / (2 pi R / N): curves "
      << a.curve_max_ratio << ", facets " << a.facet_max_ratio << " (mean " << a.facet_mean_ratio
      << "); " << results.sizing_seconds << " s\n";
  }
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

}  // namespace rdmesh::run
