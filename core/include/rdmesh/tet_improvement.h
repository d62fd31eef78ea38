// A local improvement of a tetrahedral mesh, as FEM meshers do after
// generation (Klingner & Shewchuk, "Aggressive tetrahedral mesh improvement",
// 2007): edge removals (3-2, 4-4 and larger rings), 2-3 face flips and
// smoothing of free vertices, applied to the worst tetrahedra first and kept
// only when they strictly raise the smallest dihedral angle of the
// tetrahedra they replace.
//
// What never changes: the vertices' indices, every boundary and interface
// triangle (TetMesh::triangles) with its patch, the feature edges and
// corners and the vertices on them. Without a surface, the region of each
// subdomain does not change either (a flip re-tiles a region of one
// subdomain; a moved vertex lies on no triangle, feature edge or corner, and
// its tetrahedra keep one label). With the exact surface (BoundarySurface),
// a vertex on the triangles of one patch only may also slide along that
// patch: it stays on the patch (the oracle's projection), its triangles keep
// their normals within 20 degrees of the input's and stay within the facet
// distance of the patch, so the regions change only within what the facet
// distance allows. Every tetrahedron stays positively oriented by CGAL's
// exact orientation predicate. The result depends only on the input mesh and
// surface (fixed order: by angle, then by index), unless a time limit stops it.
#pragma once

#include "rdmesh/geometry.h"
#include "rdmesh/optimization.h"
#include "rdmesh/oracle.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh {

/// The exact surface the mesh's triangles follow: the oracle it was made from
/// and the criteria's facet distance. Without an oracle no boundary vertex moves.
struct BoundarySurface {
  const DomainOracle* oracle = nullptr;
  ScalarField facet_distance;
};

/// Improves `mesh` in place (a first-order, unpartitioned mesh with positively
/// oriented tetrahedra), moving boundary vertices along `surface` when it has an
/// oracle and options.boundary_moves is set. Throws InputError for a
/// second-order or partitioned mesh.
TetImprovementStats improve_tets(TetMesh& mesh, const TetImprovementOptions& options = {},
                                 const BoundarySurface& surface = {});

}  // namespace rdmesh
