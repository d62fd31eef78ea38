#include "rdmesh/run_setup.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "rdmesh/arguments.h"
#include "rdmesh/atomic_file.h"
#include "rdmesh/cad_layer.h"
#include "rdmesh/errors.h"
#include "rdmesh/feature_name.h"
#include "rdmesh/input_file.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/parallel_for.h"
#include "rdmesh/sha256.h"
#include "rdmesh/triangle_mesh_oracle.h"

namespace rdmesh::run {
namespace fs = std::filesystem;

void add_write_options(CLI::App& app, WriteOptions& write) {
  auto* binary = app.add_flag_callback(
      "--binary", [&write] { write.encoding = Encoding::binary; },
      "Binary output: .msh 4.1 binary, .vtu zlib-compressed (default: binary above 1e6 "
      "elements)");
  app.add_flag_callback(
         "--ascii", [&write] { write.encoding = Encoding::ascii; },
         "Text output whatever the mesh's size")
      ->excludes(binary);
  app.add_option("--format", write.msh22,
                 "The .msh version: 'msh41' (Gmsh 4.1; default) or 'msh22' (Gmsh 2.2 ASCII, for "
                 "older solvers)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, bool>{{"msh41", false}, {"msh22", true}}, CLI::ignore_case));
}

void add_options(CLI::App& app, Options& opt) {
  app.add_option("input", opt.input,
                 "Domain: .json implicit domain file, a .step/.stp/.brep/.iges/.igs CAD model, or "
                 "a closed .off/.stl/.obj/.ply triangle mesh")
      ->required();
  app.add_option(
      "-o,--output", opt.output,
      "Output mesh: .mesh (Medit), .msh (Gmsh 4.1) or .vtu (VTK); default INPUT-stem.msh");
  app.add_option("--size", opt.size,
                 "Target size h: edge, facet and cell size = h, facet distance h/10")
      ->check(finite_number());
  app.add_option("--edge-size", opt.edge_size,
                 "Max radius of restricted edge balls on sharp curves (R2); default: facet size")
      ->check(finite_number());
  app.add_option("--facet-size", opt.facet_size, "Max radius of surface Delaunay balls (R4.1)")
      ->check(finite_number());
  app.add_option("--cell-size", opt.cell_size, "Max circumradius of tetrahedra (R5.1)")
      ->check(finite_number());
  app.add_option("--facet-distance", opt.facet_distance,
                 "Max distance between a boundary facet's circumcenter and the surface")
      ->check(finite_number());
  app.add_option("--facet-angle", opt.facet_angle,
                 "Min angle of boundary facets, degrees (default 25)")
      ->check(finite_number());
  app.add_option("--radius-edge", opt.radius_edge,
                 "Max radius-edge ratio of tetrahedra (default 2)")
      ->check(finite_number());
  app.add_option(
         "--min-size", opt.min_size,
         "Termination guard: no two vertices closer than this (default 1e-4 of the box diagonal)")
      ->check(finite_number());
  app.add_option("--max-elements", opt.max_elements,
                 "Refuse criteria whose estimated element count exceeds this (default 5e7)")
      ->check(finite_number())
      ->check(CLI::PositiveNumber);
  app.add_flag("--no-exude", opt.no_exude, "Skip sliver exudation after refinement");
  const CLI::Validator seconds(
      [](std::string& v) -> std::string {
        try {
          const double s = std::stod(v);
          if (s >= 0 && std::isfinite(s)) return {};
        } catch (const std::exception&) {
        }
        return "must be a number of seconds >= 0 (0 = no limit), got '" + v + "'";
      },
      "SECONDS");
  app.add_option("--exude-time-limit", opt.exude_time_limit,
                 "Stop sliver exudation after this many seconds (default: no limit)")
      ->check(seconds);
  app.add_option("--exude-bound", opt.exude_bound,
                 "Sliver exudation treats the vertices of tetrahedra whose smallest dihedral "
                 "angle is below this, degrees (default 25; lower is faster, with more "
                 "tetrahedra left between it and 25)")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            try {
              const double deg = std::stod(v);
              if (deg > 0 && deg <= 90) return {};
            } catch (const std::exception&) {
            }
            return "must be an angle in degrees in (0, 90], got '" + v + "'";
          },
          "DEG"));
  app.add_flag("--no-optimize", opt.no_optimize,
               "Keep the restricted Delaunay tetrahedra: no final flips and vertex moves "
               "against the worst dihedral angles");
  app.add_option("--threads", opt.threads,
                 "Threads for the refinement's surface and cell centres, exudation, "
                 "improvement and the report; the output is the same for any number "
                 "(default 0: all cores)")
      ->check(CLI::Range(0, 1024));
  app.add_option("--report", opt.report, "Write a JSON report of the run to this file");
  app.add_flag("-q,--quiet", opt.quiet, "No progress and no summary");
  app.add_flag("--heal", opt.heal,
               "CAD input: run OpenCASCADE shape healing first and report what it changed");
  app.add_option("--features", opt.features,
                 "How sharp curves and corners are meshed: 'protect' (protecting balls, any "
                 "angles; default) or 'refine' (RR-7912's rules R1/R2, needs features meeting at "
                 ">= 90 degrees)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, FeatureMethod>{{"protect", FeatureMethod::kProtectingBalls},
                                               {"refine", FeatureMethod::kRefineEdges}},
          CLI::ignore_case));
  app.add_flag("--surface-only", opt.surface_only,
               "Mesh the surface patches only (triangles, feature edges, corners; no "
               "tetrahedra); a triangle-mesh input may then be open");
  app.add_option("--feature-angle", opt.feature_angle,
                 "Triangle-mesh input: an edge is a sharp curve when its two triangles' normals "
                 "turn by more than this, degrees (default 60)")
      ->check(finite_number())
      ->check(CLI::Range(0.0, 180.0));
  app.add_option("--time-limit", opt.time_limit,
                 "Stop meshing (protection, initial points, refinement) after this many "
                 "seconds; the run then fails (exit 4) (default: no limit)")
      ->check(seconds);
  app.add_flag("--keep-bad-mesh", opt.keep_bad_mesh,
               "Write the mesh even when it fails the fidelity check or the time limit "
               "stopped it (the exit code is still 4)");
  app.add_option("--check", opt.full_check,
                 "Fidelity check: 'cheap' (volumes, patches, curve chains; default) or 'full' "
                 "(also every boundary triangle's distance to its surface; also with --report)")
      ->transform(CLI::CheckedTransformer(
          std::map<std::string, bool>{{"cheap", false}, {"full", true}}, CLI::ignore_case));
  add_write_options(app, opt.write);
  app.add_option("--picture", opt.picture.path,
                 "Also write a picture of the mesh (.png): the boundary and a cut view");
  add_picture_options(app, opt.picture);
  add_fem_options(app, opt.fem);
}

LoadedInput load_input(const Options& opt) {
  const std::string& path = opt.input;
  if (is_cad_file(path)) {
    CadLayer::Loaded cad = cad_layer().load(path, opt.heal);
    if (opt.heal) {
      for (const std::string& line : cad.log) std::cerr << path << ": " << line << "\n";
    }
    for (const std::string& w : cad.warnings) {
      std::cerr << "rdmesh: warning: " << path << ": " << w << "\n";
    }
    return {std::move(cad.oracle), {}};
  }
  const std::string ext = lower_extension(path);
  if (ext == ".json") {
    LoadedDomain d = load_domain_file(path);
    return {std::move(d.oracle), std::move(d.hints)};
  }
  if (ext == ".off" || ext == ".stl" || ext == ".obj" || ext == ".ply") {
    TriangleMeshOptions options;
    options.feature_angle_degrees = opt.feature_angle;
    options.surface_only = opt.surface_only;
    try {
      return {TriangleMeshOracle::from_file(path, options), {}};
    } catch (const InputError& e) {
      const std::string what = e.what();
      if (opt.surface_only || what.find("not closed") == std::string::npos) throw;
      throw InputError(what +
                       " (a volume needs closed surfaces; --surface-only meshes an open "
                       "surface without its volume)");
    }
  }
  throw InputError(
      path, "unknown input extension '" + ext +
                "' (expected .json, .step, .stp, .brep, .iges, .igs, .off, .stl, .obj or .ply)");
}

namespace {

/// Whether `a` and `b` name the same file (existing or not).
bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (fs::equivalent(a, b, ec)) return true;
  const fs::path ca = fs::weakly_canonical(a, ec);
  if (ec) return false;
  const fs::path cb = fs::weakly_canonical(b, ec);
  return !ec && ca == cb;
}

}  // namespace

void check_paths(const Options& opt) {
  check_input_file(opt.input);
  check_output_names(opt);
}

void check_output_names(const Options& opt) {
  const std::pair<const char*, const std::string*> outputs[] = {
      {"-o", &opt.output}, {"--report", &opt.report}, {"--picture", &opt.picture.path}};
  for (std::size_t i = 0; i < std::size(outputs); ++i) {
    const std::string& out = *outputs[i].second;
    if (out.empty()) continue;
    if (same_file(opt.input, out)) {
      throw InputError(opt.input, std::string(outputs[i].first) + " " + out +
                                      " is the input file: it would be overwritten");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (!outputs[j].second->empty() && same_file(*outputs[j].second, out)) {
        throw InputError(opt.input, std::string(outputs[i].first) + " " + out + " is also the " +
                                        outputs[j].first + " output: give them different names");
      }
    }
  }
}

std::string printable(const std::string& message) {
  std::string out;
  for (const char c : message) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (u < 0x20 || u == 0x7f) {
      static const char* hex = "0123456789abcdef";
      out += {'\\', 'x', hex[u >> 4], hex[u & 15]};
    } else {
      out += c;
    }
  }
  return out;
}

void check_writable(const std::string& path) {
  const fs::path dir = fs::path(path).has_parent_path() ? fs::path(path).parent_path() : ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw OutputError(path + ": directory '" + dir.string() + "' does not exist");
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    throw OutputError(path + ": directory '" + dir.string() + "' is not writable");
  }
  if (fs::is_directory(path, ec)) throw OutputError(path + ": is a directory");
}

std::string default_output_path(const std::string& input) {
  return fs::path(input).stem().string() + ".msh";
}

Criteria resolve_criteria(const Options& opt, const LoadedInput& input) {
  Criteria c = default_criteria(input.oracle->bounding_box());
  const CriteriaHints& h = input.hints;
  // File hints: size sets both sizes; specific keys refine it.
  std::optional<ScalarField> size = h.size;
  if (opt.size) size = ScalarField::uniform(*opt.size);
  if (size) c.facet_size = c.cell_size = *size;
  if (h.facet_size && !opt.size) c.facet_size = *h.facet_size;
  if (h.cell_size && !opt.size) c.cell_size = *h.cell_size;
  if (opt.facet_size) c.facet_size = ScalarField::uniform(*opt.facet_size);
  if (opt.cell_size) c.cell_size = ScalarField::uniform(*opt.cell_size);
  // Curves follow the facet size unless told otherwise.
  c.edge_size = c.facet_size;
  if (h.edge_size && !opt.size) c.edge_size = *h.edge_size;
  if (opt.edge_size) c.edge_size = ScalarField::uniform(*opt.edge_size);
  // Facet distance follows the facet size (1/10) unless given.
  const Point3 center = input.oracle->bounding_box().center();
  c.facet_distance = 0.1 * c.facet_size(center);
  if (h.facet_distance) c.facet_distance = *h.facet_distance;
  if (opt.facet_distance) c.facet_distance = *opt.facet_distance;
  if (h.facet_angle) c.facet_angle_deg = *h.facet_angle;
  if (opt.facet_angle) c.facet_angle_deg = *opt.facet_angle;
  if (h.radius_edge) c.cell_radius_edge = *h.radius_edge;
  if (opt.radius_edge) c.cell_radius_edge = *opt.radius_edge;
  if (opt.min_size) c.min_size = *opt.min_size;
  // CAD models without sizes asked: follow the thickness of slender parts.
  const CadLayer* cad = cad_layer_of(*input.oracle);
  if (cad && !opt.size && !opt.facet_size && !opt.cell_size && !opt.edge_size) {
    cad->follow_thickness(*input.oracle, c,
                          {!h.facet_distance && !opt.facet_distance, !opt.min_size});
  }
  try {
    c.validate();
    c.min_size = c.min_size_for(input.oracle->bounding_box());  // the report shows it
    double curve_length = 0;
    for (const CurveInfo& info : input.oracle->curves()) {
      curve_length += input.oracle->curve(info.id).length(info.t_begin, info.t_end);
    }
    check_feasible(c, input.oracle->bounding_box(), curve_length, opt.max_elements);
  } catch (const InputError& e) {
    throw InputError(opt.input, e.what());
  }
  return c;
}

ExudationOptions exudation_options(const Options& opt) {
  ExudationOptions o;
  o.enabled = !opt.no_exude;
  o.time_limit_seconds = opt.exude_time_limit;
  o.sliver_bound_deg = opt.exude_bound;
  return o;
}

TetImprovementOptions improvement_options(const Options& opt) {
  TetImprovementOptions o;
  o.enabled = !opt.no_optimize;
  return o;
}

namespace {

/// A uniform size as its value; a varying one as {"varying": true, "min", "max"} over
/// the 16^3 grid of nodes of `box` that check_feasible samples.
nlohmann::json field_json(const ScalarField& f, const Box3& box) {
  if (f.is_uniform()) return f.constant;
  constexpr int kNodes = 16;
  double lo = f(box.lo), hi = lo;
  for (int i = 0; i < kNodes; ++i) {
    for (int j = 0; j < kNodes; ++j) {
      for (int k = 0; k < kNodes; ++k) {
        const auto at = [&](double a, double b, int n) { return a + (b - a) * n / (kNodes - 1); };
        const double v =
            f({at(box.lo.x, box.hi.x, i), at(box.lo.y, box.hi.y, j), at(box.lo.z, box.hi.z, k)});
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
  }
  return {{"varying", true}, {"min", lo}, {"max", hi}};
}

bool is_triangle_mesh(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".off" || ext == ".stl" || ext == ".obj" || ext == ".ply";
}

/// Every criterion and setting as the run used it (defaults resolved).
nlohmann::json criteria_json(const Options& opt, const Criteria& criteria, const Box3& box) {
  nlohmann::json c = {
      {"edge_size", field_json(criteria.edge_size, box)},
      {"facet_size", field_json(criteria.facet_size, box)},
      {"cell_size", field_json(criteria.cell_size, box)},
      {"facet_distance", field_json(criteria.facet_distance, box)},
      {"facet_angle_deg", criteria.facet_angle_deg},
      {"cell_radius_edge", criteria.cell_radius_edge},
      {"min_size", criteria.min_size},
      {"max_elements", opt.max_elements},
      {"features", opt.features == FeatureMethod::kRefineEdges ? "refine" : "protect"},
      {"surface_only", opt.surface_only},
      {"exudation", !opt.no_exude && !opt.surface_only},
      {"exude_time_limit_s", opt.exude_time_limit},
      {"exude_bound_deg", opt.exude_bound},
      {"threads", resolve_threads(opt.threads)},
      {"optimize", !opt.no_optimize && !opt.surface_only},
      {"time_limit_s", opt.time_limit},
      {"check", opt.full_check || !opt.report.empty() ? "full" : "cheap"}};
  if (is_triangle_mesh(opt.input)) c["feature_angle_deg"] = opt.feature_angle;
  if (is_cad_file(opt.input)) c["heal"] = opt.heal;
  return c;
}

}  // namespace

nlohmann::json report_json(const Options& opt, const Criteria& criteria, const DomainOracle& oracle,
                           const RefinementStats& stats, const ExudationStats& exudation,
                           const TetImprovementStats& improvement, const QualityReport& quality,
                           const std::optional<FidelityReport>& fidelity, const RunTimes& times,
                           const FemResults& fem) {
  nlohmann::json j = to_json(quality);
  j.update(fem_json(fem));
  j["rdmesh_version"] = RDMESH_VERSION;
  j["command_line"] = opt.command_line;
  j["input"] = opt.input;
  // A Python run's input may be no file (a callable, an rdmesh.Oracle).
  j["input_sha256"] = fs::is_regular_file(opt.input) ? nlohmann::json(sha256_of_file(opt.input))
                                                     : nlohmann::json(nullptr);
  j["output"] = opt.output;
  j["criteria"] = criteria_json(opt, criteria, oracle.bounding_box());
  if (const CadLayer* cad = cad_layer_of(oracle)) {
    for (auto& patch : j["patches"]) {
      const std::string color = cad->patch_color(oracle, PatchId(patch.at("id").get<int>()));
      if (!color.empty()) patch["color"] = color;
    }
  }
  j["refinement"] = {{"initial_points", stats.initial_points},
                     {"edge_centers_inserted", stats.inserted_edge_centers},
                     {"facet_centers_inserted", stats.inserted_facet_centers},
                     {"cell_centers_inserted", stats.inserted_cell_centers},
                     {"cell_centers_in_lanes", stats.cell_centers_in_lanes},
                     {"facet_centers_in_lanes", stats.facet_centers_in_lanes},
                     {"lane_rounds", stats.lane_rounds},
                     {"lane_steps", stats.lane_steps},
                     {"lane_threads", stats.lane_threads},
                     {"encroachments", stats.encroachments},
                     {"time_limit_reached", stats.time_limit_reached},
                     {"elements_left", stats.elements_left}};
  if (stats.time_limit_reached) j["refinement"]["stopped_in"] = phase_name(stats.stopped_in);
  j["fidelity"] = fidelity ? to_json(*fidelity) : nlohmann::json(nullptr);
  j["guard"] = {{"fired", stats.guard_fired()},
                {"rejected_points", stats.guard_rejections},
                {"features", stats.guard_features}};
  j["protection"] = {
      {"balls", stats.protecting_balls},       {"min_ball_radius", stats.min_ball_radius},
      {"restarts", stats.protection_restarts}, {"conflicts", stats.protection_conflicts},
      {"features", stats.protection_features}, {"seconds", stats.seconds_protect}};
  j["unmeshed_feature_edges"] = stats.unmeshed_feature_edges;
  j["missing_patches"] = nlohmann::json::array();
  for (const PatchId& p : stats.missing_patches) j["missing_patches"].push_back(p.value);
  j["exudation"] = {{"ran", exudation.ran},
                    {"min_dihedral_before_deg", exudation.min_dihedral_before_deg},
                    {"min_dihedral_after_deg", exudation.min_dihedral_after_deg},
                    {"histogram_bucket_deg", 5},
                    {"histogram_before", exudation.histogram_before},
                    {"histogram_after", exudation.histogram_after},
                    {"moves_tried", exudation.moves_tried},
                    {"moves_accepted", exudation.moves_accepted},
                    {"moves_tried_in_lanes", exudation.moves_tried_in_lanes},
                    {"time_limit_reached", exudation.time_limit_reached},
                    {"seconds", exudation.seconds}};
  j["optimization"] = {{"ran", improvement.ran},
                       {"min_dihedral_before_deg", improvement.min_dihedral_before_deg},
                       {"min_dihedral_after_deg", improvement.min_dihedral_after_deg},
                       {"histogram_bucket_deg", 5},
                       {"histogram_before", improvement.histogram_before},
                       {"histogram_after", improvement.histogram_after},
                       {"tets_before", improvement.tets_before},
                       {"tets_after", improvement.tets_after},
                       {"face_flips", improvement.face_flips},
                       {"edge_removals", improvement.edge_removals},
                       {"vertex_moves", improvement.vertex_moves},
                       {"boundary_moves", improvement.boundary_moves},
                       {"curve_moves", improvement.curve_moves},
                       {"vertex_insertions", improvement.vertex_insertions},
                       {"sweeps", improvement.sweeps},
                       {"time_limit_reached", improvement.time_limit_reached},
                       {"seconds", improvement.seconds}};
  j["seconds"] = {{"load", times.load},
                  {"protect", stats.seconds_protect},
                  {"initial_points", stats.seconds_initial},
                  {"refine", stats.seconds_refine},
                  {"exude", exudation.seconds},
                  {"extract", stats.seconds_extract},
                  {"optimize", improvement.seconds},
                  {"write", times.write},
                  {"report", times.report}};
  return j;
}

std::string input_error_message(const InputError& e, const std::string& input) {
  return e.file().empty() ? input + ": " + e.what() : e.what();
}

void check_outputs(const Options& opt) {
  if (!opt.output.empty()) {
    check_output_format(opt.output, opt.write);  // unknown extension, binary Medit...
    check_writable(opt.output);
  }
  check_fem_options(opt.fem, opt.input, opt.output, opt.surface_only, opt.write.msh22);
  if (!opt.report.empty()) check_writable(opt.report);
  if (!opt.picture.path.empty()) (void)picture_options(opt.picture, opt.input);
}

void check_output_format(const std::string& path, const WriteOptions& write) {
  try {
    (void)writes_binary(TetMesh{}, format_from_path(path), write);
  } catch (const InputError& e) {
    if (!e.file().empty()) throw;
    throw InputError(path, e.what());
  }
}

std::vector<std::string> run_warnings(const RefinementStats& stats) {
  std::vector<std::string> out;
  for (const PatchId& patch : stats.missing_patches) {
    out.push_back(feature_name(patch) +
                  " has no triangle in the mesh (too small for the sizes, or missed by the "
                  "initial points)");
  }
  const auto joined = [](const std::vector<std::string>& items) {
    std::string s;
    for (const std::string& f : items) s += (s.empty() ? "" : "; ") + f;
    return s;
  };
  if (stats.guard_fired()) {
    out.push_back("the minimum-size guard refused " + std::to_string(stats.guard_rejections) +
                  " refinement points (" + joined(stats.guard_features) +
                  "); the input may violate the angle hypothesis of RR-7912 (features meeting "
                  "below 90 degrees)");
  }
  if (stats.protection_conflicts > 0) {
    out.push_back(std::to_string(stats.protection_conflicts) +
                  " protecting balls could not be made small enough (" +
                  joined(stats.protection_features) +
                  "): features closer than the minimum size; the mesh may miss them there");
  }
  if (stats.unmeshed_feature_edges > 0) {
    out.push_back(std::to_string(stats.unmeshed_feature_edges) +
                  " feature edges are not edges of the mesh");
  }
  return out;
}

std::string format_run_summary(const Options& opt, const RefinementStats& stats,
                               const ExudationStats& exudation,
                               const TetImprovementStats& improvement, const RunTimes& times,
                               bool wrote_mesh) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(2);
  s << "refinement: " << stats.initial_points << " initial points, " << stats.inserted_edge_centers
    << " edge centers, " << stats.inserted_facet_centers << " facet centers, "
    << stats.inserted_cell_centers << " cell centers, " << stats.encroachments
    << " encroachments\n";
  if (stats.protecting_balls > 0) {
    s.precision(3);
    s << "protection: " << stats.protecting_balls << " balls, smallest radius " << std::defaultfloat
      << stats.min_ball_radius << std::fixed << ", " << stats.protection_restarts << " restarts, "
      << stats.protection_conflicts << " conflicts left\n";
    s.precision(2);
  }
  s << "guard: " << (stats.guard_fired() ? "FIRED" : "not fired") << " (" << stats.guard_rejections
    << " points refused)\n";
  if (opt.surface_only) {
    s << "exudation: none (surface only)\n";
  } else if (exudation.ran) {
    s << "exudation: min dihedral " << exudation.min_dihedral_before_deg << " -> "
      << exudation.min_dihedral_after_deg << " deg, tets below 10 deg "
      << exudation.histogram_before[0] + exudation.histogram_before[1] << " -> "
      << exudation.histogram_after[0] + exudation.histogram_after[1] << ", "
      << exudation.moves_accepted << " of " << exudation.moves_tried << " moves"
      << (exudation.time_limit_reached ? " (time limit reached)" : "") << '\n';
  } else {
    s << "exudation: off\n";
  }
  if (opt.surface_only) {
    s << "optimization: none (surface only)\n";
  } else if (improvement.ran) {
    s << "optimization: min dihedral " << improvement.min_dihedral_before_deg << " -> "
      << improvement.min_dihedral_after_deg << " deg, tets below 10 deg "
      << improvement.histogram_before[0] + improvement.histogram_before[1] << " -> "
      << improvement.histogram_after[0] + improvement.histogram_after[1] << ", "
      << improvement.edge_removals << " edge removals, " << improvement.face_flips
      << " face flips, " << improvement.vertex_moves << " vertex moves, "
      << improvement.boundary_moves << " moves along patches, " << improvement.curve_moves
      << " along curves, " << improvement.vertex_insertions << " new vertices"
      << (improvement.time_limit_reached ? " (time limit reached)" : "") << '\n';
  } else {
    s << "optimization: off\n";
  }
  // Times with 3 significant digits (%g): a short phase reads 0.00312 s, not 0.00 s.
  const auto sec = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, v >= 100 ? "%.0f" : "%.3g", v);
    return std::string(text);
  };
  s << "time: load " << sec(times.load) << " s, protect " << sec(stats.seconds_protect)
    << " s, refine " << sec(stats.seconds_initial + stats.seconds_refine) << " s, exude "
    << sec(exudation.seconds) << " s, extract " << sec(stats.seconds_extract) << " s, optimize "
    << sec(improvement.seconds) << " s, write " << sec(times.write) << " s, report "
    << sec(times.report) << " s\n";
  if (wrote_mesh) {
    s << "wrote " << opt.output << (opt.report.empty() ? "" : " and " + opt.report)
      << (opt.picture.path.empty() ? "" : " and " + opt.picture.path) << '\n';
  } else {
    s << "no mesh written" << (opt.report.empty() ? "" : "; wrote " + opt.report) << '\n';
  }
  return s.str();
}

}  // namespace rdmesh::run
