// Re-triangulating a hole as the cone from an existing vertex.
//
// Exudation changes a vertex's weight in place: the cells the new weight
// conflicts with form a hole around the vertex, and the hole is re-triangulated
// as the cone from that same vertex, so that its handle, its info (feature,
// curve parameter, ball) and every queue entry naming it stay valid. Removal
// followed by insertion would create a new vertex. The triangulation data
// structure's insert_in_hole(..., newv) does the cone with a given vertex; it is
// documented in the TriangulationDataStructure_3 concept but rarely used, and it
// was once reached through the undocumented _insert_in_hole. It is called here
// only, and tests/core/cone_hole_test.cpp checks what exudation relies on against
// a regular triangulation built from scratch, so a CGAL upgrade that changes it
// fails there first.
#pragma once

#include <vector>

#include "../triangulation_types.h"

namespace rdmesh::detail {

/// Replaces the cells of `hole` (the conflict zone of v's new weighted point; their
/// union a region star-shaped from v's position, bounded by facets whose far side
/// stays) by the cone from v over the hole's boundary. (boundary_cell,
/// boundary_facet) is any facet of the boundary, seen from a cell of the hole.
/// The caller sets v's new point afterwards. The cells of `hole` are destroyed.
void cone_hole(Triangulation& tr, const std::vector<Cell_handle>& hole, Cell_handle boundary_cell,
               int boundary_facet, Vertex_handle v);

}  // namespace rdmesh::detail
