// rdmesh command line: INPUT [-o OUTPUT] [criteria] [--report FILE.json] [--quiet].
// Every failure is one line "rdmesh: error: ..." on stderr and a non-zero exit
// (2 for bad input or an unwritable output); no partial output file is left.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

#include "arguments.h"
#include "heap_setup.h"
#include "model_measures.h"
#include "progress_display.h"
#include "rdmesh/errors.h"
#include "rdmesh/fidelity.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/mesher.h"
#include "rdmesh/number_text.h"
#include "rdmesh/quality_report.h"
#include "run_setup.h"
#include "view_command.h"

namespace {

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "rdmesh: error: %s\n", rdmesh::cli::printable(message).c_str());
  return code;
}

int run(const rdmesh::cli::Options& opt) {
  using namespace rdmesh;
  const auto start = std::chrono::steady_clock::now();
  cli::check_paths(opt);
  try {  // unknown extension, binary Medit...: fail before meshing
    (void)writes_binary(TetMesh{}, format_from_path(opt.output), opt.write);
  } catch (const InputError& e) {
    if (!e.file().empty()) throw;
    throw InputError(opt.output, e.what());
  }
  cli::check_writable(opt.output);
  cli::check_fem_options(opt.fem, opt.input, opt.output, opt.surface_only);
  if (!opt.report.empty()) cli::check_writable(opt.report);
  if (!opt.picture.path.empty()) (void)cli::picture_options(opt.picture, opt.input);

  cli::ProgressDisplay progress(!opt.quiet);
  progress.phase("reading " + cli::printable(opt.input));
  cli::LoadedInput input = cli::load_input(opt);
  progress.phase("checking the criteria");
  Criteria criteria = cli::resolve_criteria(opt, input);
  const std::vector<EntitySize> sizes = cli::apply_size_options(opt.fem, *input.oracle, criteria);
  const double seconds_load =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  MeshOptions mesh_options;
  mesh_options.progress = [&progress](const Progress& p) { progress(p); };
  mesh_options.exudation = cli::exudation_options(opt);
  mesh_options.features = opt.features;
  mesh_options.surface_only = opt.surface_only;
  mesh_options.time_limit_seconds = opt.time_limit;
  MeshResult result = generate_mesh(*input.oracle, criteria, mesh_options);

  // The cheap measures and the fidelity check first: a mesh that does not
  // match the model is not written (unless asked).
  auto t = std::chrono::steady_clock::now();
  progress.phase("checking the mesh against the model");
  const bool full = opt.full_check || !opt.report.empty();
  const QualityReport quality = measure_quality(result.mesh, full ? input.oracle.get() : nullptr);
  std::optional<FidelityReport> fidelity;
  if (const auto model = cli::model_measures(*input.oracle, opt.surface_only)) {
    fidelity = check_fidelity(quality, *model, input.oracle->patches(), input.oracle->curves(),
                              patch_facet_distances(result.mesh, criteria.facet_distance),
                              result.stats.curves_below_min_size);
  }
  const double seconds_report =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  const bool bad = result.stats.time_limit_reached || (fidelity && !fidelity->passed);

  cli::FemResults fem;  // timed on its own, in its summary line
  if (!bad || opt.keep_bad_mesh) {
    if (opt.fem.order == 2) progress.phase("making second-order elements");
    if (opt.fem.order != 2 && opt.fem.partitions > 0) progress.phase("partitioning");
    fem = cli::apply_fem_options(opt.fem, sizes, result.mesh, *input.oracle);
  }
  t = std::chrono::steady_clock::now();
  if (!bad || opt.keep_bad_mesh) {
    progress.phase("writing " + cli::printable(opt.output));
    write_mesh(result.mesh, opt.output, opt.write);
    if (!opt.picture.path.empty()) {
      progress.phase("drawing " + cli::printable(opt.picture.path));
      cli::write_picture(result.mesh, opt.picture, opt.input);
    }
  }
  const double seconds_write =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();

  const cli::RunTimes times{seconds_load, seconds_write, seconds_report};
  if (!opt.report.empty()) {
    progress.phase("writing " + cli::printable(opt.report));
    cli::write_json_report(opt, criteria, *input.oracle, result.stats, result.exudation, quality,
                           fidelity, times, fem);
  }
  progress.finish();
  if (!opt.quiet) {
    std::cout << format_summary(quality) << cli::format_fem_summary(fem)
              << cli::format_run_summary(opt, result.stats, result.exudation, times,
                                         !bad || opt.keep_bad_mesh);
  }
  for (const PatchId& patch : result.stats.missing_patches) {
    std::fprintf(stderr, "rdmesh: warning: patch %d has no triangle in the mesh (too small for "
                 "the sizes, or missed by the initial points)\n", patch.value);
  }
  if (result.stats.guard_fired()) {
    std::string where;
    for (const std::string& f : result.stats.guard_features) where += (where.empty() ? "" : "; ") + f;
    std::fprintf(stderr,
                 "rdmesh: warning: the minimum-size guard refused %zu refinement points (%s); the "
                 "input may violate the angle hypothesis of RR-7912 (features meeting below 90 "
                 "degrees)\n",
                 result.stats.guard_rejections, where.c_str());
  }
  if (result.stats.protection_conflicts > 0) {
    std::string where;
    for (const std::string& f : result.stats.protection_features) where += (where.empty() ? "" : "; ") + f;
    std::fprintf(stderr,
                 "rdmesh: warning: %zu protecting balls could not be made small enough (%s): "
                 "features closer than the minimum size; the mesh may miss them there\n",
                 result.stats.protection_conflicts, where.c_str());
  }
  if (result.stats.unmeshed_feature_edges > 0) {
    std::fprintf(stderr, "rdmesh: warning: %zu feature edges are not edges of the mesh\n",
                 result.stats.unmeshed_feature_edges);
  }
  if (!bad) return 0;
  const std::string what =
      result.stats.time_limit_reached
          ? "refinement stopped at the time limit (" + short_number(opt.time_limit) +
                " s) with " + std::to_string(result.stats.elements_left) +
                " elements still queued"
          : "the mesh does not match the model: " + summarize_problems(*fidelity);
  return fail(4, opt.input + ": " + what +
                     (opt.keep_bad_mesh ? " (written anyway: --keep-bad-mesh)"
                                        : "; no mesh written (--keep-bad-mesh writes it)"));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "view") return rdmesh::cli::run_view_command(argc - 1, argv + 1);
  rdmesh::cli::setup_heap();
  CLI::App app{"rdmesh: tetrahedral meshes of domains bounded by piecewise smooth surfaces"};
  app.set_version_flag("--version", "rdmesh " RDMESH_VERSION);
  rdmesh::cli::Options opt;
  rdmesh::cli::add_options(app, opt);
  rdmesh::cli::add_fem_options(app, opt.fem);
  opt.command_line = rdmesh::cli::command_line_text(argc, argv);
  if (const auto flag = rdmesh::cli::single_dash_option(argc, argv, "oqh")) {
    return fail(2, rdmesh::cli::unknown_single_dash_message(*flag, "rdmesh"));
  }
  try {
    app.parse(argc, argv);
    if (opt.output.empty()) opt.output = rdmesh::cli::default_output_path(opt.input);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    return fail(2, (opt.input.empty() ? std::string() : opt.input + ": ") +
                       rdmesh::cli::parse_error_message(e, app, "rdmesh"));
  }
  try {
    return run(opt);
  } catch (const rdmesh::InputError& e) {
    // The library's errors about the run (criteria too coarse for the domain)
    // name no file: the input is the one.
    return fail(2, e.file().empty() ? opt.input + ": " + e.what() : e.what());
  } catch (const rdmesh::OutputError& e) {
    return fail(2, e.what());
  } catch (const rdmesh::Error& e) {
    return fail(3, e.what());
  } catch (const std::bad_alloc&) {
    return fail(3, "out of memory");
  } catch (const std::exception& e) {
    return fail(3, std::string("internal error: ") + e.what());
  }
}
