// A local improvement of a tetrahedral mesh, as FEM meshers do after
// generation (Klingner & Shewchuk, "Aggressive tetrahedral mesh improvement",
// 2007): edge removals (3-2, 4-4 and larger rings), 2-3 face flips and
// smoothing of free vertices, applied to the worst tetrahedra first and kept
// only when they strictly raise the smallest dihedral angle of the
// tetrahedra they replace.
//
// What never changes: the vertices' indices, every boundary and interface
// triangle (TetMesh::triangles) with its patch, the feature edges and
// corners, and the region of each subdomain (a flip re-tiles a region of
// one subdomain; a moved vertex lies on no triangle, feature edge or corner,
// and its tetrahedra keep one label). Every tetrahedron stays positively
// oriented by CGAL's exact orientation predicate. The result depends only on
// the input mesh (fixed order: by angle, then by index), unless a time limit
// stops it.
#pragma once

#include "rdmesh/optimization.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh {

/// Improves `mesh` in place (a first-order, unpartitioned mesh with positively
/// oriented tetrahedra). Throws InputError for a second-order or partitioned mesh.
TetImprovementStats improve_tets(TetMesh& mesh, const TetImprovementOptions& options = {});

}  // namespace rdmesh
