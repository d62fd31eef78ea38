// The Python module rdmesh._rdmesh: meshing entry points over rdmesh_run (the
// command line's own option parsing and run), the Mesh object, rdmesh.Oracle
// and the exceptions. The public API is rdmesh/__init__.py.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "py_callables.h"
#include "py_mesh.h"
#include "py_oracle.h"
#include "rdmesh/arguments.h"
#include "rdmesh/domain_file.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_run.h"
#include "rdmesh/run_setup.h"
#include "rdmesh/stopwatch.h"

namespace py = pybind11;

namespace rdmesh::python {
namespace {

/// A run that failed its fidelity check, has inverted tetrahedra or met its
/// time limit (the CLI's exit code 4).
class FidelityError : public Error {
 public:
  using Error::Error;
};

/// The CLI's options that a Python run takes as keywords: all but --help and
/// --quiet (a Python run prints nothing; progress= shows the phases).
bool python_option(const std::string& long_name) {
  return long_name != "help" && long_name != "quiet";
}

/// [(long name, takes a value)] of the CLI's options usable from Python.
std::vector<std::pair<std::string, bool>> option_names() {
  CLI::App app;
  run::Options opt;
  run::add_options(app, opt);
  std::vector<std::pair<std::string, bool>> out;
  for (const CLI::Option* o : app.get_options()) {
    if (o->get_lnames().empty() || !python_option(o->get_lnames().front())) continue;
    out.emplace_back(o->get_lnames().front(), o->get_items_expected_min() > 0);
  }
  return out;
}

/// Parses `args` ("--name=value" or "--flag") with the CLI's own parser and
/// wording, as `rdmesh INPUT ARGS...` would; no default output (a Python run
/// writes only what output=, report= and picture= ask for).
run::Options parse_options(const std::string& input, const std::vector<std::string>& args) {
  CLI::App app;
  run::Options opt;
  run::add_options(app, opt);
  std::vector<std::string> argv(args.rbegin(), args.rend());  // CLI11 wants them reversed
  argv.push_back(input);
  try {
    app.parse(argv);
  } catch (const CLI::ParseError& e) {
    throw InputError(input, run::parse_error_message(e, app, "rdmesh"));
  }
  std::vector<const char*> words{"rdmesh", input.c_str()};
  for (const std::string& a : args) words.push_back(a.c_str());
  opt.command_line =
      "python: " + run::command_line_text(static_cast<int>(words.size()), words.data());
  opt.quiet = true;
  return opt;
}

py::dict progress_dict(const Progress& p) {
  py::dict d;
  d["phase"] = p.phase;
  d["vertices"] = p.vertices;
  d["edge_queue"] = p.edge_queue;
  d["facet_queue"] = p.facet_queue;
  d["cell_queue"] = p.cell_queue;
  d["elapsed_seconds"] = p.elapsed_seconds;
  return d;
}

/// The progress callback of a run: KeyboardInterrupt (Ctrl-C) and the user's
/// callback, with the GIL taken for them.
/// `progress` outlives the run; the std::function holds a pointer to it, as it
/// is copied without the GIL.
MeshOptions progress_options(const py::object& progress) {
  MeshOptions options;
  options.progress = [callback = &progress](const Progress& p) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // KeyboardInterrupt
    if (!callback->is_none()) (*callback)(progress_dict(p));
  };
  return options;
}

/// Criteria, meshing, the fidelity check, the FEM options, the outputs asked
/// for and the report of a loaded input: the CLI's run (cli/main.cpp) with
/// exceptions instead of exit codes. `release_gil`: no Python code in the
/// oracle, so other threads may run.
PyMesh mesh_input(const run::Options& opt, const run::LoadedInput& input,
                  const py::object& progress, bool release_gil, double seconds_load) {
  MeshOptions options = progress_options(progress);
  // Python code in the oracle needs the GIL, which this thread keeps: every
  // query stays here.
  options.oracle_concurrent = release_gil;
  std::optional<py::gil_scoped_release> release;
  if (release_gil) release.emplace();
  run::announce(options, "checking the criteria");
  Criteria criteria = run::resolve_criteria(opt, input);
  const run::AppliedSizes sizes =
      run::apply_size_options(opt.fem, input.hints.sizes, *input.oracle, criteria);
  run::MeshRun run = run::mesh_loaded(opt, input, criteria, options);
  run.times.load = seconds_load;
  const bool bad = run.failed();
  if (!bad || opt.keep_bad_mesh) run::apply_fem(opt, sizes, *input.oracle, options, run);
  run::write_outputs(opt, *input.oracle, options, !bad || opt.keep_bad_mesh, run);
  release.reset();
  if (bad && !opt.keep_bad_mesh) {
    throw FidelityError(opt.input + ": " + run::failure_reason(opt, run) +
                        "; no mesh returned (keep_bad_mesh=True returns it)");
  }
  PyMesh out;
  out.report_json = run::run_report(opt, *input.oracle, run).dump();
  out.failed = bad;
  out.warnings = run::run_warnings(run.result.stats);
  for (const std::string& w : out.warnings) {
    if (PyErr_WarnEx(PyExc_RuntimeWarning, w.c_str(), 1) != 0) throw py::error_already_set();
  }
  out.mesh = std::move(run.result.mesh);
  return out;
}

/// Calls `run`, giving the library's bad-input errors the CLI's one-line
/// message (run::input_error_message).
template <class Run>
PyMesh naming_input(const std::string& input, Run run) {
  try {
    return run();
  } catch (const InputError& e) {
    if (!e.file().empty()) throw;
    throw InputError(run::input_error_message(e, input));
  }
}

PyMesh mesh_file(const std::string& path, const std::vector<std::string>& args,
                 const py::object& progress) {
  const Stopwatch clock;
  const run::Options opt = parse_options(path, args);
  return naming_input(path, [&] {
    run::check_paths(opt);
    run::check_outputs(opt);
    run::LoadedInput input;
    {
      const MeshOptions options = progress_options(progress);
      run::announce(options, "reading " + run::printable(opt.input));
      py::gil_scoped_release release;
      input = run::load_input(opt);
    }
    PyMesh out = mesh_input(opt, input, progress, true, clock.seconds());
    out.input = path;
    return out;
  });
}

/// A domain document (the .json format); `functions` and `curves` hold the
/// callables its {"external": KEY} entries name: KEY -> (f, vectorized) and
/// KEY -> (gamma, t0, t1).
PyMesh mesh_json(const std::string& text, const std::string& origin, const py::dict& functions,
                 const py::dict& curves, const std::vector<std::string>& args,
                 const py::object& progress) {
  const Stopwatch clock;
  const run::Options opt = parse_options(origin, args);
  run::check_output_names(opt);
  run::check_outputs(opt);
  ExternalDefinitions external;
  for (const auto& item : functions) {
    const py::tuple t = item.second.cast<py::tuple>();
    external.functions[py::str(item.first)] = external_function(t[0], t[1].cast<bool>());
  }
  for (const auto& item : curves) {
    const std::string key = py::str(item.first);
    const py::tuple t = item.second.cast<py::tuple>();
    try {
      external.curves[key] = external_curve(t[0], t[1].cast<double>(), t[2].cast<double>(), key);
    } catch (const InputError& e) {
      throw InputError(origin, e.what());
    }
  }
  run::LoadedInput input;
  {
    std::optional<py::gil_scoped_release> release;
    if (external.functions.empty() && external.curves.empty()) release.emplace();
    LoadedDomain d = parse_domain_json(text, origin, external);
    input.oracle = std::move(d.oracle);
    input.hints = std::move(d.hints);
  }
  const bool pure = external.functions.empty() && external.curves.empty();
  return naming_input(origin,
                      [&] { return mesh_input(opt, input, progress, pure, clock.seconds()); });
}

PyMesh mesh_oracle(PyOracleBase& oracle, const std::vector<std::string>& args,
                   const py::object& progress) {
  const run::Options opt = parse_options("rdmesh.Oracle", args);
  run::check_output_names(opt);
  run::check_outputs(opt);
  run::LoadedInput input;
  input.oracle = std::shared_ptr<DomainOracle>(&oracle, [](DomainOracle*) {});  // lent
  return naming_input(opt.input, [&] { return mesh_input(opt, input, progress, false, 0.0); });
}

}  // namespace
}  // namespace rdmesh::python

PYBIND11_MODULE(_rdmesh, m) {
  using namespace rdmesh::python;
  m.doc() = "rdmesh's C++ side; use the rdmesh package";
  m.attr("__version__") = RDMESH_VERSION;
  const py::object error = py::register_exception<rdmesh::Error>(m, "Error", PyExc_RuntimeError);
  py::register_exception<rdmesh::InputError>(m, "InputError", error.ptr());
  py::register_exception<rdmesh::OracleError>(m, "OracleError", error.ptr());
  py::register_exception<rdmesh::OutputError>(m, "OutputError", error.ptr());
  py::register_exception<rdmesh::InternalError>(m, "InternalError", error.ptr());
  py::register_exception<FidelityError>(m, "FidelityError", error.ptr());
  bind_mesh(m);
  bind_oracle(m);
  m.def("_option_names", &option_names);

  m.def("_mesh_file", &mesh_file, py::arg("path"), py::arg("args"), py::arg("progress"));
  m.def("_mesh_json", &mesh_json, py::arg("text"), py::arg("origin"), py::arg("functions"),
        py::arg("curves"), py::arg("args"), py::arg("progress"));
  m.def("_mesh_oracle", &mesh_oracle, py::arg("oracle"), py::arg("args"), py::arg("progress"));
}
