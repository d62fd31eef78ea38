// Private to core/: moves of a boundary vertex along the one patch it lies on,
// for local improvement.
//
// Slivers and flat caps whose four vertices lie on the boundary survive every
// flip and every move of free vertices. A vertex on the triangles of exactly
// one patch (on no feature edge or corner) may slide along that patch: each
// trial position is projected onto the exact surface by the oracle
// (DomainOracle::project), and a position is kept only when
//   - every tetrahedron around the vertex (of either side, for an interface)
//     stays positively oriented (CGAL's exact predicate) and their smallest
//     dihedral angle strictly rises;
//   - each triangle around it keeps its normal within kMaxNormalTurnDeg of the
//     normal it had in the input mesh (no fold of the boundary);
//   - each such triangle's centroid and the midpoints of its edges at the
//     vertex stay within the facet distance of the patch (the projection's
//     distance), and, on a triangle with no vertex on a feature edge or
//     corner (where R4 bounds it), its circumcentre too, or no farther than
//     before, and its circumradius stays within the facet size at its
//     circumcentre (R4.1 bounds the surface ball, which is no smaller), or no
//     larger than before, so the boundary follows the surface and keeps the
//     sizes the criteria ask (a slide once made a torus's boundary edges 12%
//     longer than its curvature sizes).
// The climb checks the normals at every step and the distances (9 to 24
// projections) once, at the last position that keeps them.
// The triangles, their patches and the feature edges keep their vertices; the
// subdomains' volumes change only by the moved boundary's deviation, within
// what the facet distance allows.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "rdmesh/geometry.h"
#include "rdmesh/oracle.h"
#include "rdmesh/tet_mesh.h"
#include "tet_topology.h"

namespace rdmesh::detail {

/// A moved triangle's normal stays within this angle of its input normal (degrees).
inline constexpr double kMaxNormalTurnDeg = 20;

/// The boundary triangles of a mesh and the exact surface they follow.
class PatchSurface {
 public:
  PatchSurface(const TetMesh& mesh, const DomainOracle& oracle, const ScalarField& facet_distance,
               const ScalarField& edge_size, const ScalarField& facet_size);

  /// The patch (id) of vertex v when it lies on triangles of exactly one patch
  /// and on no feature edge or corner; 0 otherwise.
  int patch_of(int v) const { return v < static_cast<int>(patch_.size()) ? patch_[v] : 0; }
  /// The curve (id) of vertex v when it lies inside one chain of feature edges
  /// (two edges of one curve, not a corner); 0 otherwise.
  int curve_of(int v) const { return v < static_cast<int>(curve_.size()) ? curve_[v] : 0; }
  /// The other ends of the two feature edges at v (when curve_of(v) != 0).
  const std::array<int, 2>& chain_neighbours(int v) const { return chain_[v]; }
  const DomainOracle& oracle() const { return oracle_; }
  /// The oracle's description of curve `id` (copied once).
  const CurveInfo& curve_info(int id) const { return curves_[static_cast<std::size_t>(id) - 1]; }
  double facet_distance(const Point3& p) const { return facet_distance_(p); }
  /// R2's bound on half a feature edge, at the edge's midpoint p.
  double edge_size(const Point3& p) const { return edge_size_(p); }
  /// The point of `patch` closest to p (the oracle's projection).
  std::optional<Point3> project(const Point3& p, int patch) const;
  /// The unit normal of v's triangles with v at p (area-weighted mean); zero
  /// when they cancel.
  Point3 normal_at(const TetTopology& topo, int v, const Point3& p) const;
  /// True when v's triangles, with v at p, keep their normals within
  /// kMaxNormalTurnDeg of the input's.
  bool keeps_normals(const TetTopology& topo, int v, const Point3& p) const;
  /// True when v's triangles, with v at p, have their centroids and the
  /// midpoints of their edges at v within the facet distance of their patch, and
  /// (for those on no feature vertex, where R4 bounds it) their circumcentres
  /// within it or no farther from it than before the move, and their
  /// circumradii within the facet size or no larger than before.
  bool near_surface(const TetTopology& topo, int v, const Point3& p) const;

 private:
  const DomainOracle& oracle_;
  const ScalarField& facet_distance_;
  const ScalarField& edge_size_;
  const ScalarField& facet_size_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<Point3> normal0_;  ///< unit normal of each triangle in the input
  std::vector<int> triangle_patch_;
  std::vector<int> patch_;
  std::vector<char> feature_;  ///< on a feature edge or a corner
  std::vector<CurveInfo> curves_;
  std::vector<int> curve_;
  std::vector<std::array<int, 2>> chain_;
  std::vector<std::vector<int>> triangles_of_;
};

/// Moves vertex v (patch_of(v) != 0) along its patch to raise the smallest
/// dihedral angle of its tetrahedra; true when it moved.
bool smooth_on_patch(TetTopology& topo, const PatchSurface& surface, int v);

}  // namespace rdmesh::detail
