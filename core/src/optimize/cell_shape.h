// Private to core/: the shape of a triangulation cell as the exudation ranks
// it, and the copy of it each cell keeps during exudation
// (CellInfo::shape_cosine), so that re-ranking a vertex reads its star's
// shapes instead of recomputing them.
#pragma once

#include <limits>

#include "../triangulation_types.h"
#include "tet_shape.h"

namespace rdmesh::detail {

/// Cosine of the smallest dihedral angle of finite cell c (larger is worse).
inline double cell_cosine(Cell_handle c) {
  return max_dihedral_cosine(to_point3(c->vertex(0)->point()), to_point3(c->vertex(1)->point()),
                             to_point3(c->vertex(2)->point()), to_point3(c->vertex(3)->point()));
}

/// The shape_cosine a cell holds during exudation: its cell_cosine() for a
/// domain cell (label != 0, finite), -infinity for the others.
inline double stored_shape(const Triangulation& tr, Cell_handle c) {
  return c->info().label != 0 && !tr.is_infinite(c) ? cell_cosine(c)
                                                    : -std::numeric_limits<double>::infinity();
}

}  // namespace rdmesh::detail
