// A local improvement of a tetrahedral mesh, as FEM meshers do after
// generation (Klingner & Shewchuk, "Aggressive tetrahedral mesh improvement",
// 2007): edge removals (3-2, 4-4 and larger rings), 2-3 face flips and
// smoothing of free vertices, applied to the worst tetrahedra first and kept
// only when they strictly raise the smallest dihedral angle of the
// tetrahedra they replace.
//
// What never changes: the vertices' indices, every boundary and interface
// triangle (TetMesh::triangles) with its patch, the feature edges with their
// curves, and the corners. Without a surface, no vertex on a triangle, feature
// edge or corner moves, and the region of each subdomain does not change
// either (a flip re-tiles a region of one subdomain; a moved vertex lies on no
// triangle, and its tetrahedra keep one label). With the exact surface
// (BoundarySurface), a vertex on the triangles of one patch only may also
// slide along that patch (the oracle's projection), and a vertex between two
// feature edges of one curve (not a corner) along that curve (its exact
// points); the triangles around it keep their normals within 20 degrees of
// the input's and stay within the facet distance and the facet size of their
// patches, its
// feature edges within the facet distance of the curve, so the regions change
// only within what the facet distance allows. Every tetrahedron stays
// positively oriented by CGAL's exact orientation predicate. The result
// depends only on the input mesh and surface (fixed order: by angle, then by
// index), unless a time limit stops it.
#pragma once

#include <limits>

#include "rdmesh/geometry.h"
#include "rdmesh/optimization.h"
#include "rdmesh/oracle.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh {

/// The exact surface the mesh's triangles follow: the oracle it was made from,
/// the criteria's facet distance, their edge size (R2: half a feature edge
/// <= edge_size at its midpoint; a vertex sliding along a curve never makes a
/// feature edge break it, or longer if it already did; default: no bound) and
/// their facet size (R4.1: a vertex sliding along a patch never makes a
/// triangle's circumradius exceed facet_size at its circumcentre, or grow if
/// it already did; default: no bound). Without an oracle no boundary vertex moves.
struct BoundarySurface {
  const DomainOracle* oracle = nullptr;
  ScalarField facet_distance;
  ScalarField edge_size = ScalarField::uniform(std::numeric_limits<double>::infinity());
  ScalarField facet_size = ScalarField::uniform(std::numeric_limits<double>::infinity());
};

/// Improves `mesh` in place (a first-order, unpartitioned mesh with positively
/// oriented tetrahedra), moving boundary vertices along `surface` when it has an
/// oracle and options.boundary_moves is set. Throws InputError for a
/// second-order or partitioned mesh.
TetImprovementStats improve_tets(TetMesh& mesh, const TetImprovementOptions& options = {},
                                 const BoundarySurface& surface = {});

}  // namespace rdmesh
