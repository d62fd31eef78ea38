#include "py_mesh.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "rdmesh/arguments.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/picture_args.h"
#include "rdmesh/run_setup.h"

namespace py = pybind11;

namespace rdmesh::python {
namespace {

static_assert(sizeof(Point3) == 3 * sizeof(double));
static_assert(sizeof(SubdomainId) == sizeof(int) && sizeof(PatchId) == sizeof(int) &&
              sizeof(CurveId) == sizeof(int) && sizeof(CornerId) == sizeof(int));

/// A read-only numpy view of `count` rows of `columns` values of type T at
/// `data`, owned by `owner` (the Python Mesh).
template <class T>
py::array view(const void* data, std::size_t count, std::size_t columns, const py::object& owner) {
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(count)};
  std::vector<py::ssize_t> strides{static_cast<py::ssize_t>(columns * sizeof(T))};
  if (columns > 1) {
    shape.push_back(static_cast<py::ssize_t>(columns));
    strides.push_back(sizeof(T));
  }
  py::array a(py::dtype::of<T>(), shape, strides, static_cast<const T*>(data), owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

template <class Info>
std::vector<std::string> names(const std::vector<Info>& infos) {
  std::vector<std::string> out;
  for (const Info& i : infos) out.push_back(i.name);
  return out;
}

/// The getter of a TetMesh array member as an (n, columns) view of T.
template <class T, class Vector>
auto rows(Vector TetMesh::*member, std::size_t columns) {
  return [member, columns](const py::object& self) {
    const Vector& v = self.cast<const PyMesh&>().mesh.*member;
    return view<T>(v.data(), v.size(), columns, self);
  };
}

/// --binary, --ascii and --format as the CLI parses them ("--binary", "--format=msh22").
WriteOptions parse_write_options(const std::string& path, const std::vector<std::string>& args) {
  CLI::App app;
  WriteOptions write;
  run::add_write_options(app, write);
  std::vector<std::string> argv(args.rbegin(), args.rend());  // CLI11 wants them reversed
  try {
    app.parse(argv);
  } catch (const CLI::ParseError& e) {
    throw InputError(path, run::parse_error_message(e, app, "rdmesh"));
  }
  return write;
}

}  // namespace

void bind_mesh(py::module_& m) {
  py::class_<PyMesh>(m, "Mesh",
                     "A labelled tetrahedral mesh. Arrays are read-only numpy views of the "
                     "mesh's own storage; indices are 0-based; labels are the ids of "
                     "subdomains, patches, curves and corners (1-based, names in "
                     "subdomain_names[id - 1] etc.).")
      .def_property_readonly("points", rows<double>(&TetMesh::vertices, 3),
                             "(n, 3) float64 vertex coordinates")
      .def_property_readonly("tets", rows<int>(&TetMesh::tets, 4),
                             "(k, 4) int32, positively oriented tetrahedra")
      .def_property_readonly("tet_labels", rows<int>(&TetMesh::tet_subdomain, 1),
                             "(k,) int32 subdomain id of each tetrahedron")
      .def_property_readonly("triangles", rows<int>(&TetMesh::triangles, 3),
                             "(t, 3) int32 boundary and interface triangles")
      .def_property_readonly("triangle_labels", rows<int>(&TetMesh::triangle_patch, 1),
                             "(t,) int32 patch id of each triangle")
      .def_property_readonly("edges", rows<int>(&TetMesh::edges, 2),
                             "(e, 2) int32 feature edges (sharp curves)")
      .def_property_readonly("edge_labels", rows<int>(&TetMesh::edge_curve, 1),
                             "(e,) int32 curve id of each feature edge")
      .def_property_readonly("corners", rows<int>(&TetMesh::corner_vertices, 1),
                             "(c,) int32 vertex index of each corner")
      .def_property_readonly("corner_labels", rows<int>(&TetMesh::corner_ids, 1),
                             "(c,) int32 corner id of each corner vertex")
      .def_property_readonly("tet_mid_nodes", rows<int>(&TetMesh::tet_mid_nodes, 6),
                             "order=2: (k, 6) int32 mid-edge node of edges 01, 12, 20, 30, 32, "
                             "31 of each tetrahedron (Gmsh's order); empty for order 1")
      .def_property_readonly("triangle_mid_nodes", rows<int>(&TetMesh::triangle_mid_nodes, 3),
                             "order=2: (t, 3) int32 mid-edge nodes of edges 01, 12, 20")
      .def_property_readonly("edge_mid_nodes", rows<int>(&TetMesh::edge_mid_nodes, 1),
                             "order=2: (e,) int32 mid node of each feature edge")
      .def_property_readonly("tet_partition", rows<int>(&TetMesh::tet_partition, 1),
                             "partitions=N: (k,) int32 partition 1..N of each tetrahedron; "
                             "empty without partitions")
      .def_property_readonly("subdomain_names",
                             [](const PyMesh& p) { return names(p.mesh.subdomains); })
      .def_property_readonly("patch_names", [](const PyMesh& p) { return names(p.mesh.patches); })
      .def_property_readonly("curve_names", [](const PyMesh& p) { return names(p.mesh.curves); })
      .def_property_readonly(
          "failed", [](const PyMesh& p) { return p.failed; },
          "True when the run failed its fidelity check or time limit "
          "(returned only with keep_bad_mesh=True)")
      .def_property_readonly(
          "report",
          [](const PyMesh& p) { return py::module_::import("json").attr("loads")(p.report_json); },
          "the run's JSON report (as --report writes it) as a dict")
      .def_property_readonly(
          "warnings", [](const PyMesh& p) { return p.warnings; },
          "the run's warnings (also issued as RuntimeWarning), as the CLI prints them")
      .def(
          "_write",
          [](const PyMesh& p, const py::object& path, const std::vector<std::string>& args) {
            run::Options opt;
            opt.input = p.input;
            opt.output = py::str(py::module_::import("os").attr("fspath")(path));
            opt.write = parse_write_options(opt.output, args);
            if (!p.input.empty() && std::filesystem::exists(p.input)) run::check_paths(opt);
            run::check_output_format(opt.output, opt.write);
            if (!p.mesh.tet_partition.empty()) {  // Medit and MSH 2.2 cannot carry them
              run::FemOptions fem;
              fem.partitions = 1;
              run::check_fem_options(fem, p.input, opt.output, false, opt.write.msh22);
            }
            run::check_writable(opt.output);
            py::gil_scoped_release release;
            write_mesh(p.mesh, opt.output, opt.write);
          },
          py::arg("path"), py::arg("args"))
      .def(
          "picture",
          [](const PyMesh& p, const py::object& path, const std::string& view_dir,
             const std::string& size, const std::string& cut) {
            run::PictureArgs args;
            args.path = py::str(py::module_::import("os").attr("fspath")(path));
            args.view = view_dir;
            args.size = size;
            args.cut = cut;
            run::Options opt;
            opt.input = p.input;
            opt.picture = args;
            if (!p.input.empty() && std::filesystem::exists(p.input)) run::check_paths(opt);
            const std::string title = p.input.empty() ? std::string("rdmesh") : p.input;
            py::gil_scoped_release release;
            run::write_picture(p.mesh, args, title);
          },
          py::arg("path"), py::arg("view") = "iso", py::arg("picture_size") = "1600x900",
          py::arg("cut") = "",
          "Writes a PNG picture of the mesh (the boundary and a cut view), as rdmesh --picture");
}

}  // namespace rdmesh::python
