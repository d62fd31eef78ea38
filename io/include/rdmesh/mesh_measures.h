// Reusable geometric and topological measures of tetrahedral meshes.
//
// Plain doubles (no exact predicates): these functions measure quality and
// check topology in reports and tests; they never drive refinement decisions.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "rdmesh/geometry.h"

namespace rdmesh {

/// Euler characteristic V - E + F of a triangle set, counting only the vertices
/// used by some triangle. Duplicated triangles are counted once each in F.
/// Example: a closed sphere-like surface gives 2, a torus 0, a disk 1.
int euler_characteristic(const std::vector<std::array<int, 3>>& triangles);

/// True when every undirected edge of `triangles` is shared by exactly two
/// triangles (a closed, edge-manifold surface; vertex manifoldness is not checked).
/// An empty set is manifold.
bool is_edge_manifold(const std::vector<std::array<int, 3>>& triangles);

/// Number of connected components of the graph made of `edges` (pairs of
/// vertex indices, orientation ignored); only vertices used by some edge count,
/// so an empty set has 0 components.
int count_chain_components(const std::vector<std::array<int, 2>>& edges);

/// True when `edges` (orientation ignored) form one simple chain:
///   - closed == false: an open path, i.e. connected, two end vertices of
///     degree 1 and every other vertex of degree 2;
///   - closed == true: one cycle, i.e. connected and every vertex of degree 2.
/// A repeated edge (in either orientation), an edge from a vertex to itself,
/// a branching vertex (degree > 2) or an empty set gives false.
/// Example: {0,1},{1,2} is an open chain; {0,1},{1,2},{2,0} a closed one.
bool is_simple_chain(const std::vector<std::array<int, 2>>& edges, bool closed);

/// Signed volume (1/6) det[b-a, c-a, d-a]: positive when (a,b,c,d) is
/// positively oriented in the TetMesh sense.
double signed_volume(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

/// The six interior dihedral angles in degrees, at edges ab, ac, ad, bc, bd, cd
/// in that order. A flat tetrahedron has angles of 0 or 180 degrees; an angle
/// at an edge whose adjacent face is degenerate (zero area) is reported as 0.
std::vector<double> dihedral_angles_deg(const Point3& a, const Point3& b, const Point3& c,
                                        const Point3& d);

/// The smallest and the largest of dihedral_angles_deg(a, b, c, d), found by
/// comparing the angles without computing them: two arctangents instead of six.
std::pair<double, double> dihedral_extremes_deg(const Point3& a, const Point3& b, const Point3& c,
                                                const Point3& d);

/// Circumradius divided by the shortest edge length (sqrt(6)/4 ~ 0.612 for
/// the regular tetrahedron). +infinity for a flat tetrahedron or a zero-length edge.
double radius_edge_ratio(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

}  // namespace rdmesh
