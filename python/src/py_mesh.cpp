#include "py_mesh.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <vector>

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

PyMesh& self_of(const py::object& self) { return self.cast<PyMesh&>(); }

}  // namespace

void bind_mesh(py::module_& m) {
  py::class_<PyMesh>(m, "Mesh",
                     "A labelled tetrahedral mesh. Arrays are read-only numpy views of the "
                     "mesh's own storage; indices are 0-based; labels are the ids of "
                     "subdomains, patches, curves and corners (1-based, names in "
                     "subdomain_names[id - 1] etc.).")
      .def_property_readonly(
          "points",
          [](const py::object& s) {
            const TetMesh& t = self_of(s).mesh;
            return view<double>(t.vertices.data(), t.vertices.size(), 3, s);
          },
          "(n, 3) float64 vertex coordinates")
      .def_property_readonly(
          "tets",
          [](const py::object& s) {
            const TetMesh& t = self_of(s).mesh;
            return view<int>(t.tets.data(), t.tets.size(), 4, s);
          },
          "(k, 4) int32, positively oriented tetrahedra")
      .def_property_readonly(
          "tet_labels",
          [](const py::object& s) {
            const TetMesh& t = self_of(s).mesh;
            return view<int>(t.tet_subdomain.data(), t.tet_subdomain.size(), 1, s);
          },
          "(k,) int32 subdomain id of each tetrahedron")
      .def_property_readonly(
          "triangles",
          [](const py::object& s) {
            const TetMesh& t = self_of(s).mesh;
            return view<int>(t.triangles.data(), t.triangles.size(), 3, s);
          },
          "(t, 3) int32 boundary and interface triangles")
      .def_property_readonly(
          "triangle_labels",
          [](const py::object& s) {
            const TetMesh& t = self_of(s).mesh;
            return view<int>(t.triangle_patch.data(), t.triangle_patch.size(), 1, s);
          },
          "(t,) int32 patch id of each triangle")
      .def_property_readonly(
          "edges",
          [](const py::object& s) {
            const TetMesh& t = self_of(s).mesh;
            return view<int>(t.edges.data(), t.edges.size(), 2, s);
          },
          "(e, 2) int32 feature edges (sharp curves)")
      .def_property_readonly(
          "edge_labels",
          [](const py::object& s) {
            const TetMesh& t = self_of(s).mesh;
            return view<int>(t.edge_curve.data(), t.edge_curve.size(), 1, s);
          },
          "(e,) int32 curve id of each feature edge")
      .def_property_readonly(
          "corners",
          [](const py::object& s) {
            const TetMesh& t = self_of(s).mesh;
            return view<int>(t.corner_vertices.data(), t.corner_vertices.size(), 1, s);
          },
          "(c,) int32 vertex index of each corner")
      .def_property_readonly(
          "corner_labels",
          [](const py::object& s) {
            const TetMesh& t = self_of(s).mesh;
            return view<int>(t.corner_ids.data(), t.corner_ids.size(), 1, s);
          },
          "(c,) int32 corner id of each corner vertex")
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
      .def(
          "write",
          [](const PyMesh& p, const py::object& path) {
            run::Options opt;
            opt.input = p.input;
            opt.output = py::str(py::module_::import("os").attr("fspath")(path));
            if (!p.input.empty() && std::filesystem::exists(p.input)) run::check_paths(opt);
            (void)format_from_path(opt.output);
            run::check_writable(opt.output);
            py::gil_scoped_release release;
            write_mesh(p.mesh, opt.output);
          },
          py::arg("path"),
          "Writes .msh (Gmsh 4.1), .mesh (Medit) or .vtu (VTK) as the CLI does, atomically; "
          "never over the input file")
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
          py::arg("path"), py::arg("view") = "iso", py::arg("size") = "1600x900",
          py::arg("cut") = "",
          "Writes a PNG picture of the mesh (the boundary and a cut view), as rdmesh --picture");
}

}  // namespace rdmesh::python
