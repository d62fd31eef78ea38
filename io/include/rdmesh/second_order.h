// Second-order (P2) meshes: 10-node tetrahedra, 6-node triangles and 3-node
// feature edges built from a first-order TetMesh and the oracle it was meshed from.
//
// Every edge of the mesh gets one mid-edge node. An edge of a feature curve
// gets the point of its curve nearest to the chord's midpoint (Curve::closest
// on the arc between its two vertices); an edge of a boundary or interface
// triangle that lies on no curve gets the oracle's projection of the midpoint
// onto the triangle's patch (for CAD models: Newton on the face's own surface);
// every other edge keeps the midpoint. A curved mid-edge node is never allowed
// to invert an element: the Jacobian determinant of a 10-node tetrahedron is a
// cubic polynomial, whose 20 Bernstein coefficients bound it from below and
// above (tet10_jacobian); where the smallest coefficient is not above
// `min_scaled_jacobian` times the largest, the curved nodes of that
// tetrahedron are moved back to their chords' midpoints ("straightened") and
// its neighbours checked again, until every tetrahedron passes (a straight
// tetrahedron always does: its determinant is constant and positive).
#pragma once

#include <array>
#include <cstddef>

#include "rdmesh/oracle.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh {

struct SecondOrderOptions {
  /// Certified lower bound of min det J / max det J that every tetrahedron
  /// with curved nodes must exceed; in [0, 1). 0 only refuses inverted
  /// (or degenerate) elements.
  double min_scaled_jacobian = 0.05;
};

struct SecondOrderStats {
  std::size_t mid_nodes = 0;      ///< nodes added (one per edge of the mesh)
  std::size_t curve_nodes = 0;    ///< mid nodes placed on a feature curve
  std::size_t surface_nodes = 0;  ///< mid nodes placed on a patch
  std::size_t straightened = 0;   ///< curved nodes moved back to the chord to keep Jacobians valid
  std::size_t placement_failures = 0;  ///< boundary nodes left on the chord: the projection failed
                                       ///< or landed more than half the edge away
  /// Smallest certified min det J / max det J over the tetrahedra (1 for a
  /// straight-sided one); 1 when the mesh has no tetrahedra.
  double min_scaled_jacobian = 1;
  /// Largest distance from a curved node to its chord's midpoint, relative
  /// to the edge's length.
  double max_relative_offset = 0;
  double seconds = 0;
};

/// Adds the mid-edge nodes to `mesh` (a first-order mesh made for `oracle`):
/// fills TetMesh::tet_mid_nodes, triangle_mid_nodes and edge_mid_nodes and
/// appends the nodes to TetMesh::vertices, in the order of the sorted vertex
/// pairs (deterministic). Throws InputError if the mesh is already second
/// order or `options` is out of range; exceptions of the oracle go through.
SecondOrderStats make_second_order(TetMesh& mesh, const DomainOracle& oracle,
                                   const SecondOrderOptions& options = {});

/// True when `mesh` has second-order nodes.
bool is_second_order(const TetMesh& mesh);

/// Bounds of the Jacobian determinant of a 10-node tetrahedron whose nodes
/// are given in Gmsh's order (the four vertices, then the mid nodes of edges
/// 01, 12, 20, 30, 32, 31), on the reference tetrahedron of volume 1/6.
struct JacobianBounds {
  double lower = 0;   ///< smallest Bernstein coefficient: det J >= lower everywhere
  double upper = 0;   ///< largest Bernstein coefficient: det J <= upper everywhere
  double volume = 0;  ///< the element's exact volume (integral of det J)
  /// lower / upper when upper > 0, else lower (<= 0): a certified lower bound
  /// of min det J / max det J, 1 for a straight-sided element.
  double scaled() const { return upper > 0 ? lower / upper : lower; }
};
JacobianBounds tet10_jacobian(const std::array<Point3, 10>& nodes);

/// The ten nodes of tetrahedron `t` of a second-order mesh, in Gmsh's order.
std::array<Point3, 10> tet10_nodes(const TetMesh& mesh, std::size_t t);

/// The volume of the mesh's tetrahedra labelled `id` (all of them when id is
/// 0): exact for the curved elements of a second-order mesh, the sum of the
/// straight tetrahedra's volumes for a first-order one.
double mesh_volume(const TetMesh& mesh, SubdomainId id = SubdomainId(0));

}  // namespace rdmesh
