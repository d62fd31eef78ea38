// The Python Mesh object: a TetMesh with its report, its arrays as numpy
// views that keep the object alive (no copies).
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "rdmesh/tet_mesh.h"

namespace rdmesh::python {

struct PyMesh {
  TetMesh mesh;
  std::string report_json;            ///< run_report(), parsed by Python on access
  std::string input;                  ///< the input file, never overwritten by write(); empty: none
  bool failed = false;                ///< kept with keep_bad_mesh although the run failed
  std::vector<std::string> warnings;  ///< run::run_warnings
};

void bind_mesh(pybind11::module_& m);

}  // namespace rdmesh::python
