// Python callables as the library's functions: implicit functions (point by
// point with floats, the box sampling's grid at once with numpy arrays) and
// parametric curves. Called with the GIL held; a Python exception becomes
// pybind11::error_already_set, which unwinds the run back to Python.
#pragma once

#include <pybind11/pybind11.h>

#include "rdmesh/domain_file.h"

namespace rdmesh::python {

/// f(x, y, z) with floats for single points and with three (n,) float64 arrays
/// for the sampling grid (`vectorized`: otherwise floats only); returns a
/// number, or an (n,) array (or a scalar to broadcast) for arrays.
ExternalFunction external_function(pybind11::object f, bool vectorized);

/// gamma(t) -> (x, y, z) on [t0, t1], called with floats. Throws InputError
/// "curve 'NAME': ..." as ParametricCurve does.
ImplicitCurveSpec external_curve(pybind11::object gamma, double t0, double t1,
                                 const std::string& name);

}  // namespace rdmesh::python
