#include "cone_hole.h"

#include <algorithm>

#include "rdmesh/debug_assert.h"

namespace rdmesh::detail {

void cone_hole(Triangulation& tr, const std::vector<Cell_handle>& hole, Cell_handle boundary_cell,
               int boundary_facet, Vertex_handle v) {
  RDMESH_DEBUG_ASSERT(std::find(hole.begin(), hole.end(), boundary_cell) != hole.end() &&
                          std::find(hole.begin(), hole.end(),
                                    boundary_cell->neighbor(boundary_facet)) == hole.end(),
                      "the start facet lies on the hole's boundary, seen from inside");
  // Marks the hole's cells in conflict (how it finds the hole's extent), then cones.
  tr.tds().insert_in_hole(hole.begin(), hole.end(), boundary_cell, boundary_facet, v);
}

}  // namespace rdmesh::detail
