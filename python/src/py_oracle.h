// rdmesh.Oracle: a DomainOracle written in Python. A subclass defines
// bounding_box, locate, subdomains, patches, initial_points, project and
// tolerance, and may define intersect (else DomainOracle's bisection on
// locate()) (see rdmesh/__init__.py); sharp features (curves,
// corners) are not offered to Python oracles. Every query is a Python call
// made with the GIL held: orders of magnitude slower than a C++ oracle or an
// expression, which is why the constant answers (box, subdomains, patches,
// tolerance) are asked once and kept.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <vector>

#include "rdmesh/oracle.h"

namespace rdmesh::python {

/// The class Python subclasses; smooth (DomainOracle's feature defaults).
class PyOracleBase : public DomainOracle {};

void bind_oracle(pybind11::module_& m);

}  // namespace rdmesh::python
