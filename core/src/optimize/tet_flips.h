// Private to core/: topological flips of local improvement, inside one
// subdomain and away from every constrained triangle and edge.
//
// Edge removal (Shewchuk, "Two discrete optimization algorithms for the
// topological improvement of tetrahedral meshes", 2002): the n tetrahedra
// around an edge ab (3-2 for n = 3, 4-4 for n = 4) are replaced by the
// 2(n - 2) tetrahedra joining a and b to a triangulation of their ring, the
// one that maximizes the smallest dihedral angle (dynamic programming over
// the ring's triangulations). The 2-3 flip replaces the two tetrahedra on a
// face by three around the edge joining their apexes.
//
// Every new tetrahedron must be positively oriented (CGAL's exact predicate)
// in the order that makes the new tetrahedra a consistently oriented
// triangulation of the old ones' boundary: they then tile exactly the region
// the old ones tiled, so volumes, labels and every face on that boundary stay.
#pragma once

#include <vector>

#include "tet_topology.h"

namespace rdmesh::detail {

/// Tetrahedra to remove and to add in one subdomain, with the smallest
/// dihedral angle (degrees) of each set.
struct LocalChange {
  std::vector<int> removed;
  std::vector<Tet> added;
  int label = 0;
  double before = 0;
  double after = -1;
  bool improves() const { return after > before; }
};

/// The best removal of edge (a, b) when it is legal (an unconstrained edge
/// inside one subdomain with a closed ring of 3 to 8 tetrahedra); false otherwise.
bool plan_edge_removal(const TetTopology& topo, int a, int b, LocalChange& change);

/// The 2-3 flip of the face of tetrahedron t opposite its vertex t[i], when
/// that face is unconstrained, inside one subdomain and the flip is valid.
bool plan_face_flip(const TetTopology& topo, int t, int i, LocalChange& change);

/// Applies `change`.
void apply(TetTopology& topo, const LocalChange& change);

}  // namespace rdmesh::detail
