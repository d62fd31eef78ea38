#include "rdmesh/fem_options.h"

#include <charconv>
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
  app.add_option("--grade", opt.grade,
                 "Entity sizes grow by at most this factor from one element to the next (> 1; "
                 "default 1.4)");
}

std::vector<EntitySize> apply_size_options(const FemOptions& opt, const DomainOracle& oracle,
                                           Criteria& criteria) {
  std::vector<std::string> specs = opt.size_on;
  double grade = 1.4;
  if (!opt.sizes_file.empty()) {
    std::ifstream in(opt.sizes_file);
    if (!in) throw InputError(opt.sizes_file, "cannot read the sizes file");
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
      throw InputError(opt.sizes_file, std::string("not JSON: ") + e.what());
    }
    if (!j.is_object()) throw InputError(opt.sizes_file, "expected an object of sizes");
    for (const auto& [key, value] : j.items()) {
      if (!value.is_number()) {
        throw InputError(opt.sizes_file, "'" + key + "' must be a number");
      }
      if (key == "grade") {
        grade = value.get<double>();
      } else {
        char text[32];
        const auto end = std::to_chars(text, text + sizeof text, value.get<double>()).ptr;
        specs.push_back(key + "=" + std::string(text, end));
      }
    }
  }
  if (opt.grade) grade = *opt.grade;
  std::vector<EntitySize> sizes;
  for (const std::string& s : specs) sizes.push_back(parse_entity_size(s, oracle));
  apply_entity_sizes(oracle, sizes, grade, criteria);
  return sizes;
}

void check_fem_options(const FemOptions& opt, const std::string& input, const std::string& output,
                       bool surface_only) {
  if (opt.partitions == 0) return;
  if (surface_only) {
    throw InputError(input, "--partitions needs tetrahedra: it cannot go with --surface-only");
  }
  if (!output.empty() && format_from_path(output) == MeshFormat::Medit) {
    throw InputError(output,
                     "a Medit file cannot carry partitions (--partitions): write .msh or .vtu");
  }
}

FemResults apply_fem_options(const FemOptions& opt, const std::vector<EntitySize>& sizes,
                             TetMesh& mesh, const DomainOracle& oracle) {
  FemResults r;
  r.sizes = achieved_sizes(mesh, sizes);
  r.grade = opt.grade.value_or(1.4);
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
