// The pieces of a meshing run between argument parsing and meshing, shared by
// the CLI and the Python module: options and their CLI11 parser, input loading
// by extension, criteria resolution (bbox defaults < file < options) and the
// run report.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "rdmesh/criteria.h"
#include "rdmesh/domain_file.h"
#include "rdmesh/errors.h"
#include "rdmesh/fem_options.h"
#include "rdmesh/fidelity.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/mesher.h"
#include "rdmesh/oracle.h"
#include "rdmesh/picture_args.h"
#include "rdmesh/quality_report.h"

namespace rdmesh::run {

struct Options {
  std::string command_line;  ///< argv quoted for a shell, for the report
  std::string input;
  std::string output;  ///< default: the input's stem + ".msh" in the current directory
  std::optional<double> size, edge_size, facet_size, cell_size, facet_distance, facet_angle,
      radius_edge, min_size;
  double max_elements = kDefaultMaxElements;  ///< --max-elements: limit of the size estimate
  bool no_exude = false;                      ///< --no-exude
  bool no_optimize = false;                   ///< --no-optimize: keep the restricted Delaunay tets
  double exude_time_limit = 0;                ///< --exude-time-limit SECONDS, 0 = none
  /// --exude-bound DEG: exudation pumps the vertices of tets below this angle.
  double exude_bound = ExudationOptions{}.sliver_bound_deg;
  int threads = 0;     ///< --threads N, 0 = all cores
  std::string report;  ///< JSON report path, empty = none
  bool quiet = false;
  bool heal = false;          ///< --heal: OpenCASCADE shape healing of CAD input
  double feature_angle = 60;  ///< --feature-angle DEG: sharp-edge threshold of triangle-mesh input
  FeatureMethod features = FeatureMethod::kProtectingBalls;  ///< --features protect|refine
  bool surface_only = false;   ///< --surface-only: triangles only, open meshes accepted
  PictureArgs picture;         ///< --picture FILE.png and its options
  double time_limit = 0;       ///< --time-limit SECONDS: stop refinement, 0 = none
  bool keep_bad_mesh = false;  ///< --keep-bad-mesh: write a mesh that failed the fidelity check
  bool full_check = false;     ///< --check full (or --report): measure every distance
  FemOptions fem;              ///< --order (fem_options.h)
  WriteOptions write;          ///< --binary / --ascii, --format msh41|msh22
};

/// --binary, --ascii and --format (msh41|msh22).
void add_write_options(CLI::App& app, WriteOptions& write);

/// Every option of a meshing run, --order and the entity sizes (add_fem_options) included.
void add_options(CLI::App& app, Options& opt);

/// The input's oracle and the criteria its file suggests.
struct LoadedInput {
  std::shared_ptr<DomainOracle> oracle;  ///< shared: the Python module lends its oracles
  CriteriaHints hints;
};

/// Reads opt.input, choosing the reader by extension: .json implicit domain,
/// CAD model (healed first with opt.heal; what healing changed goes to stderr),
/// triangle mesh (sharp edges above opt.feature_angle degrees). Throws
/// InputError naming the file.
LoadedInput load_input(const Options& opt);

/// Before anything else: the input exists and is a regular readable file, and no
/// output (-o, --report, --picture) is the input or another output. Throws
/// InputError naming the input.
void check_paths(const Options& opt);

/// check_paths without the input: no output is the input or another output (the
/// input of a Python run may be no file).
void check_output_names(const Options& opt);

/// Before meshing, what the outputs asked for (-o, --report, --picture; empty:
/// none) would refuse: check_output_format, check_writable, check_fem_options,
/// the picture options. Throws InputError / OutputError.
void check_outputs(const Options& opt);

/// `message` with control characters escaped (\n, \t, \xNN): one printable line.
std::string printable(const std::string& message);

/// Throws OutputError early (before meshing) when `path` cannot be written.
void check_writable(const std::string& path);

/// Bounding-box defaults, overridden by the file's hints, overridden by options; the
/// minimum size resolved (1e-4 of the box diagonal unless given); criteria that cannot
/// give a bounded mesh (check_feasible, with opt.max_elements) refused with InputError.
Criteria resolve_criteria(const Options& opt, const LoadedInput& input);

/// The optimizers' settings from the options (--no-exude, --exude-time-limit).
ExudationOptions exudation_options(const Options& opt);
/// The final improvement's settings from the options (--no-optimize).
TetImprovementOptions improvement_options(const Options& opt);

struct RunTimes {
  double load = 0, write = 0, report = 0;
};

/// The report: version, command line, the input's SHA-256, every criterion as used (varying
/// sizes as their min and max over the oracle's box), the quality (with the CAD model's
/// patch colours), the fidelity, the phases and the second-order results. "input_sha256" is
/// null when the input is no file (a Python callable or oracle).
nlohmann::json report_json(const Options& opt, const Criteria& criteria, const DomainOracle& oracle,
                           const RefinementStats& stats, const ExudationStats& exudation,
                           const TetImprovementStats& improvement, const QualityReport& quality,
                           const std::optional<FidelityReport>& fidelity, const RunTimes& times,
                           const FemResults& fem = {});

/// The one-line message of a bad-input error of a run on `input`: the library's
/// errors about the run itself (criteria too coarse for the domain) name no
/// file, and the input is the one.
std::string input_error_message(const InputError& e, const std::string& input);

/// Throws InputError naming `path` when the mesh cannot be written there as asked:
/// an unknown extension, a binary Medit file. Before meshing.
void check_output_format(const std::string& path, const WriteOptions& write);

/// The run's warnings, one line each without the "rdmesh: warning: " prefix:
/// patches without triangles, the guard fired, protection conflicts, feature
/// edges left out.
std::vector<std::string> run_warnings(const RefinementStats& stats);

/// `wrote_mesh`: false when the fidelity check (or the time limit) kept the mesh from being
/// written.
std::string format_run_summary(const Options& opt, const RefinementStats& stats,
                               const ExudationStats& exudation,
                               const TetImprovementStats& improvement, const RunTimes& times,
                               bool wrote_mesh = true);

}  // namespace rdmesh::run

namespace rdmesh::run {
/// INPUT's stem with the .msh extension, in the current directory.
std::string default_output_path(const std::string& input);
}  // namespace rdmesh::run
