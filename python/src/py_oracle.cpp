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

  /// locate(p), or locate(p, hint) when the Python method takes a second
  /// argument: the hint is None or ((x, y, z), label), a point whose label is
  /// known. It may return the label, or (label, crossing) with crossing None
  /// or ((x, y, z), patch), a crossing of [p, hint point] as intersect() would
  /// give it (DomainOracle::locate).
  Located locate(const Point3& p,
                 const std::optional<LocateHint>& hint = std::nullopt) const override {
    py::gil_scoped_acquire gil;
    const py::function f = method("locate");
    if (!locate_takes_hint_) locate_takes_hint_ = accepts_two_arguments(f);
    py::object r;
    if (*locate_takes_hint_) {
      const py::object h =
          hint ? py::object(py::make_tuple(from_point(hint->point), hint->label.value))
               : py::none();
      r = f(from_point(p), h);
    } else {
      r = f(from_point(p));
    }
    if (py::isinstance<py::int_>(r)) return {SubdomainId(r.cast<int>()), std::nullopt};
    const py::sequence s = py::reinterpret_borrow<py::sequence>(r);
    if (!PySequence_Check(r.ptr()) || s.size() != 2) {
      throw OracleError("rdmesh.Oracle.locate must return a label or (label, crossing)");
    }
    return {SubdomainId(s[0].cast<int>()), hit_of(s[1], "locate")};
  }

  /// The Python method, or DomainOracle's default (bisection on locate())
  /// when the subclass does not define intersect.
  std::optional<SurfaceHit> intersect(const Point3& a, const Point3& b) const override {
    {
      py::gil_scoped_acquire gil;
      const py::function f = py::get_override(static_cast<const PyOracleBase*>(this), "intersect");
      if (f) return hit_of(f(from_point(a), from_point(b)), "intersect");
    }
    return DomainOracle::intersect(a, b);
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
  /// The subclass's method `name` (the GIL held); OracleError when it has none.
  py::function method(const char* name) const {
    const py::function f = py::get_override(static_cast<const PyOracleBase*>(this), name);
    if (!f) throw OracleError(std::string("rdmesh.Oracle subclass does not define ") + name + "()");
    return f;
  }

  template <class... Args>
  py::object call(const char* name, Args&&... args) const {
    py::gil_scoped_acquire gil;
    return method(name)(std::forward<Args>(args)...);
  }

  /// Whether the bound method f can be called with two positional arguments.
  static bool accepts_two_arguments(const py::function& f) {
    const py::object signature = py::module_::import("inspect").attr("signature")(f);
    try {
      signature.attr("bind")(py::none(), py::none());
      return true;
    } catch (const py::error_already_set& e) {
      if (!e.matches(PyExc_TypeError)) throw;
      return false;
    }
  }

  /// None, or ((x, y, z), patch) from `what`.
  static std::optional<SurfaceHit> hit_of(const py::object& r, const char* what) {
    if (r.is_none()) return std::nullopt;
    const py::sequence s = py::reinterpret_borrow<py::sequence>(r);
    if (!PySequence_Check(r.ptr()) || s.size() != 2) {
      throw OracleError(std::string("rdmesh.Oracle.") + what +
                        " must give a crossing as None or ((x, y, z), patch)");
    }
    return SurfaceHit{to_point(s[0], what), PatchId(s[1].cast<int>())};
  }

  mutable std::optional<bool> locate_takes_hint_;  // set under the GIL

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
      or locate(p, hint), when it takes a second argument: hint is None or
      ((x, y, z), label), a point whose label is known, to walk from; it may
      then return (label, crossing), crossing None or ((x, y, z), patch) on
      [p, hint point] (what intersect would return), which the refiner reuses
  intersect(a, b) -> None or ((x, y, z), patch): a crossing of the segment
      [a, b] with a patch, at least whenever locate(a) != locate(b). Optional:
      without it, rdmesh bisects [a, b] on locate() down to tolerance()
      (log2(|b - a| / tolerance) locate calls per query; a closed form is faster)
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
