// Private to core/: insertion of a new free vertex for local improvement,
// where no flip helps and no vertex of a bad tetrahedron may move (slivers
// and flat caps whose four vertices lie on features or patches).
//
// The cavity is the tetrahedron and its neighbours across unconstrained
// faces inside the same subdomain (one, two or three faces away); it is refused when a constrained
// face or edge would be inside it or a vertex would lose its last tetrahedron. The new vertex is
// joined to every face on the cavity's boundary; each new tetrahedron must be positively oriented
// (CGAL's exact predicate), so the new ones tile exactly the cavity (same region, same volume,
// boundary faces kept). Candidate positions: the centroids of the cavity's tetrahedra and of its
// vertices; from the best valid one the new vertex climbs the smallest angle
// of its star (tet_smoothing.h), and the insertion is kept when that strictly
// raises the smallest dihedral angle of the cavity.
#pragma once

#include "rdmesh/geometry.h"
#include "tet_flips.h"

namespace rdmesh::detail {

/// Plans the insertion of vertex number `new_vertex` (the next one) at
/// `where` to remove tetrahedron t, with the neighbours `levels` faces away
/// in the cavity; false when no candidate improves.
bool plan_insertion(const TetTopology& topo, int t, int levels, int new_vertex, Point3& where,
                    LocalChange& change);

}  // namespace rdmesh::detail
