// rdmesh command line: INPUT [-o OUTPUT] [criteria] [--report FILE.json] [--quiet].
// Every failure is one line "rdmesh: error: ..." on stderr and a non-zero exit
// (2 for bad input or an unwritable output); no partial output file is left.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

#include "heap_setup.h"
#include "progress_display.h"
#include "rdmesh/arguments.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_run.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/mesher.h"
#include "rdmesh/parallel_for.h"
#include "rdmesh/quality_report.h"
#include "rdmesh/run_setup.h"
#include "rdmesh/stopwatch.h"
#include "view_command.h"

namespace {

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "rdmesh: error: %s\n", rdmesh::run::printable(message).c_str());
  return code;
}

int mesh_command(const rdmesh::run::Options& opt) {
  using namespace rdmesh;
  const Stopwatch clock;
  run::check_paths(opt);
  run::check_outputs(opt);

  cli::ProgressDisplay progress(!opt.quiet);
  progress.phase("reading " + run::printable(opt.input));
  const run::LoadedInput input = run::load_input(opt);
  progress.phase("checking the criteria");
  Criteria criteria = run::resolve_criteria(opt, input);
  const run::AppliedSizes sizes =
      run::apply_size_options(opt.fem, input.hints.sizes, *input.oracle, criteria);
  const double seconds_load = clock.seconds();

  MeshOptions mesh_options;
  mesh_options.progress = [&progress](const Progress& p) { progress(p); };
  run::MeshRun mesh_run = run::mesh_loaded(opt, input, criteria, mesh_options);
  mesh_run.times.load = seconds_load;
  const MeshResult& result = mesh_run.result;
  const bool bad = mesh_run.failed();

  if (!bad || opt.keep_bad_mesh) {  // timed on its own, in its summary line
    run::apply_fem(opt, sizes, *input.oracle, mesh_options, mesh_run);
  }
  run::write_outputs(opt, *input.oracle, mesh_options, !bad || opt.keep_bad_mesh, mesh_run);
  progress.finish();
  if (!opt.quiet) {
    std::cout << format_summary(mesh_run.quality) << run::format_fem_summary(mesh_run.fem)
              << run::format_run_summary(opt, result.stats, result.exudation, result.improvement,
                                         mesh_run.times, !bad || opt.keep_bad_mesh);
  }
  for (const std::string& warning : run::run_warnings(result.stats)) {
    std::fprintf(stderr, "rdmesh: warning: %s\n", warning.c_str());
  }
  if (!bad) return 0;
  return fail(4, opt.input + ": " + run::failure_reason(opt, mesh_run) +
                     (opt.keep_bad_mesh ? " (written anyway: --keep-bad-mesh)"
                                        : "; no mesh written (--keep-bad-mesh writes it)"));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "view")
    return rdmesh::cli::run_view_command(argc - 1, argv + 1);
  rdmesh::cli::setup_heap();
  CLI::App app{"rdmesh: tetrahedral meshes of domains bounded by piecewise smooth surfaces"};
  app.set_version_flag("--version", "rdmesh " RDMESH_VERSION);
  rdmesh::run::Options opt;
  rdmesh::run::add_options(app, opt);
  opt.command_line = rdmesh::run::command_line_text(argc, argv);
  if (const auto flag = rdmesh::run::single_dash_option(argc, argv, "oqh")) {
    return fail(2, rdmesh::run::unknown_single_dash_message(*flag, "rdmesh"));
  }
  try {
    app.parse(argc, argv);
    if (opt.output.empty()) opt.output = rdmesh::run::default_output_path(opt.input);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    return fail(2, (opt.input.empty() ? std::string() : opt.input + ": ") +
                       rdmesh::run::parse_error_message(e, app, "rdmesh"));
  }
  // A run given more than one core faults its heap in on another one.
  if (rdmesh::resolve_threads(opt.threads) > 1) rdmesh::cli::start_heap_populator();
  try {
    return mesh_command(opt);
  } catch (const rdmesh::InputError& e) {
    return fail(2, rdmesh::run::input_error_message(e, opt.input));
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
