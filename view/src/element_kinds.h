// What the readers keep of an element: its kind and its corner points.
#pragma once

#include "rdmesh/view_mesh.h"

namespace rdmesh::view::detail {

/// Elements the picture draws, and the rest (counted in ViewMesh::skipped_elements).
enum class Kind { kPoint, kLine, kTriangle, kTet, kOther };

/// Appends an element whose first nodes are its corners (as in every
/// higher-order numbering of Gmsh and VTK): a point becomes a corner, a line a
/// feature edge, a triangle a boundary triangle, a tetrahedron a tetrahedron.
void add_element(ViewMesh& mesh, Kind kind, const int* nodes, int label);

}  // namespace rdmesh::view::detail
