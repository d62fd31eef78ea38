#include "py_oracle.h"

#include <pybind11/stl.h>

#include <string>

#include "rdmesh/errors.h"

namespace py = pybind11;

namespace rdmesh::python {

namespace {

Point3 to_point(const py::handle& h, const char* what) {
  const py::sequence s = py::reinterpret_borrow<py::sequence>(h);
  if (!PySequence_Check(h.ptr()) || s.size() != 3) {
    throw OracleError(std::string("rdmesh.Oracle.") + what + " must give points as (x, y, z)");
  }
  return {s[0].cast<double>(), s[1].cast<double>(), s[2].cast<double>()};
}

py::tuple from_point(const Point3& p) { return py::make_tuple(p.x, p.y, p.z); }

/// Calls the Python subclass's method `name`; OracleError when it has none.
class Trampoline final : public PyOracleBase {
 public:
  Box3 bounding_box() const override {
    if (!box_) {
      const py::object b = call("bounding_box");
      const py::sequence s = py::reinterpret_borrow<py::sequence>(b);
      if (!PySequence_Check(b.ptr()) || s.size() != 6) {
        throw OracleError(
            "rdmesh.Oracle.bounding_box must return (xmin, ymin, zmin, xmax, ymax, zmax)");
      }
      box_ = Box3{{s[0].cast<double>(), s[1].cast<double>(), s[2].cast<double>()},
                  {s[3].cast<double>(), s[4].cast<double>(), s[5].cast<double>()}};
    }
    return *box_;
  }

  /// Python's locate(p) has no hint: the refiner's walks cost one call each anyway.
  Located locate(const Point3& p, const std::optional<LocateHint>& = std::nullopt) const override {
    return {SubdomainId(call("locate", from_point(p)).cast<int>()), std::nullopt};
  }

  std::optional<SurfaceHit> intersect(const Point3& a, const Point3& b) const override {
    const py::object r = call("intersect", from_point(a), from_point(b));
    if (r.is_none()) return std::nullopt;
    const py::sequence s = py::reinterpret_borrow<py::sequence>(r);
    if (!PySequence_Check(r.ptr()) || s.size() != 2) {
      throw OracleError("rdmesh.Oracle.intersect must return None or ((x, y, z), patch)");
    }
    return SurfaceHit{to_point(s[0], "intersect"), PatchId(s[1].cast<int>())};
  }

  std::vector<SubdomainInfo> subdomains() const override {
    if (!subdomains_) {
      subdomains_.emplace();
      int id = 0;
      for (const py::handle& name : call("subdomains")) {
        subdomains_->push_back({SubdomainId(++id), py::str(name)});
      }
    }
    return *subdomains_;
  }

  std::vector<PatchInfo> patches() const override {
    if (!patches_) {
      patches_.emplace();
      int id = 0;
      for (const py::handle& h : call("patches")) {
        const py::sequence s = py::reinterpret_borrow<py::sequence>(h);
        if (!PySequence_Check(h.ptr()) || s.size() != 3) {
          throw OracleError("rdmesh.Oracle.patches must return [(name, side_a, side_b), ...]");
        }
        patches_->push_back({PatchId(++id), py::str(s[0]), SubdomainId(s[1].cast<int>()),
                             SubdomainId(s[2].cast<int>())});
      }
    }
    return *patches_;
  }

  std::vector<Point3> initial_points(PatchId patch) const override {
    std::vector<Point3> out;
    for (const py::handle& h : call("initial_points", patch.value)) {
      out.push_back(to_point(h, "initial_points"));
    }
    return out;
  }

  std::optional<Point3> project(const Point3& p, PatchId patch) const override {
    const py::object r = call("project", from_point(p), patch.value);
    if (r.is_none()) return std::nullopt;
    return to_point(r, "project");
  }

  double tolerance() const override {
    if (!tolerance_) tolerance_ = call("tolerance").cast<double>();
    return *tolerance_;
  }

 private:
  template <class... Args>
  py::object call(const char* name, Args&&... args) const {
    py::gil_scoped_acquire gil;
    const py::function f = py::get_override(static_cast<const PyOracleBase*>(this), name);
    if (!f) throw OracleError(std::string("rdmesh.Oracle subclass does not define ") + name + "()");
    return f(std::forward<Args>(args)...);
  }

  mutable std::optional<Box3> box_;
  mutable std::optional<std::vector<SubdomainInfo>> subdomains_;
  mutable std::optional<std::vector<PatchInfo>> patches_;
  mutable std::optional<double> tolerance_;
};

}  // namespace

void bind_oracle(py::module_& m) {
  py::class_<PyOracleBase, Trampoline>(m, "Oracle",
                                       R"(A domain written in Python, meshed by rdmesh.mesh_oracle.

Subclass it (calling super().__init__()) and define the queries of the C++
interface (oracles/include/rdmesh/oracle.h); points are (x, y, z) sequences:
  bounding_box() -> (xmin, ymin, zmin, xmax, ymax, zmax): contains the domain
  locate(p) -> int: the subdomain containing p, 0 outside
  intersect(a, b) -> None or ((x, y, z), patch): a crossing of the segment
      [a, b] with a patch, at least whenever locate(a) != locate(b)
  subdomains() -> [name, ...]: subdomains 1..n
  patches() -> [(name, side_a, side_b), ...]: patches 1..m, each between two
      labels (0 = outside)
  initial_points(patch) -> [(x, y, z), ...] or an (n, 3) array: points on the
      patch, at least three per connected component
  project(p, patch) -> (x, y, z) or None: the closest point of the patch
  tolerance() -> float: the accuracy of the points above
bounding_box, subdomains, patches and tolerance are asked once. Sharp curves
and corners are not offered to Python oracles. Every query is a Python call:
a Python oracle is much slower than an expression or a C++ oracle.)")
      .def(py::init<>());
}

}  // namespace rdmesh::python
