#include "py_callables.h"

#include <pybind11/numpy.h>

#include <memory>
#include <vector>

#include "rdmesh/errors.h"
#include "rdmesh/parametric_curve.h"

namespace py = pybind11;

namespace rdmesh::python {
namespace {

/// f(a, b, c) with floats through the vectorcall protocol (no tuple, no
/// pybind11 casts: this runs hundreds of thousands of times per mesh).
PyObject* call3(PyObject* f, double a, double b, double c) {
  PyObject* args[3] = {PyFloat_FromDouble(a), PyFloat_FromDouble(b), PyFloat_FromDouble(c)};
  PyObject* r =
      (args[0] && args[1] && args[2]) ? PyObject_Vectorcall(f, args, 3, nullptr) : nullptr;
  Py_XDECREF(args[0]);
  Py_XDECREF(args[1]);
  Py_XDECREF(args[2]);
  if (!r) throw py::error_already_set();
  return r;
}

double as_double(PyObject* r) {
  const double v = PyFloat_AsDouble(r);
  Py_DECREF(r);
  if (v == -1.0 && PyErr_Occurred()) throw py::error_already_set();
  return v;
}

/// The Python object shared by the copies of a std::function; released with the GIL.
std::shared_ptr<py::object> hold(py::object f) {
  return std::shared_ptr<py::object>(new py::object(std::move(f)), [](py::object* o) {
    py::gil_scoped_acquire gil;
    delete o;
  });
}

}  // namespace

ExternalFunction external_function(py::object f, bool vectorized) {
  if (!PyCallable_Check(f.ptr())) throw py::type_error("an implicit function must be callable");
  const std::shared_ptr<py::object> held = hold(std::move(f));
  ExternalFunction out;
  out.point = [held](const Point3& p) { return as_double(call3(held->ptr(), p.x, p.y, p.z)); };
  if (!vectorized) return out;
  out.batch = [held](const std::vector<Point3>& points, std::vector<double>& values) {
    const auto n = static_cast<py::ssize_t>(points.size());
    py::array_t<double> x(n), y(n), z(n);
    double *px = x.mutable_data(), *py_ = y.mutable_data(), *pz = z.mutable_data();
    for (py::ssize_t i = 0; i < n; ++i) {
      px[i] = points[i].x;
      py_[i] = points[i].y;
      pz[i] = points[i].z;
    }
    const py::object r = (*held)(x, y, z);
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(r);
    if (!a) throw py::error_already_set();
    const double* v = a.data();
    if (a.size() == 1) {
      values.assign(points.size(), v[0]);
    } else {
      values.assign(v, v + a.size());  // a wrong size is the oracle's InputError
    }
  };
  return out;
}

ImplicitCurveSpec external_curve(py::object gamma, double t0, double t1, const std::string& name) {
  if (!PyCallable_Check(gamma.ptr())) {
    throw InputError("curve '" + name + "': 'gamma' must be callable");
  }
  const std::shared_ptr<py::object> held = hold(std::move(gamma));
  ParametricCurve::Function function = [held](double t) {
    PyObject* args[1] = {PyFloat_FromDouble(t)};
    PyObject* r = args[0] ? PyObject_Vectorcall(held->ptr(), args, 1, nullptr) : nullptr;
    Py_XDECREF(args[0]);
    if (!r) throw py::error_already_set();
    const py::object point = py::reinterpret_steal<py::object>(r);
    const py::sequence s = py::reinterpret_borrow<py::sequence>(point);
    if (!PySequence_Check(point.ptr()) || s.size() != 3) {
      throw py::type_error("a curve's gamma(t) must return (x, y, z)");
    }
    return Point3{s[0].cast<double>(), s[1].cast<double>(), s[2].cast<double>()};
  };
  try {
    return {name, std::make_shared<ParametricCurve>(std::move(function), t0, t1), t0, t1};
  } catch (const InputError& e) {
    throw InputError("curve '" + name + "': " + e.what());
  }
}

}  // namespace rdmesh::python
