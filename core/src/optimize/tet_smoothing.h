// Private to core/: smoothing of one free vertex (on no triangle, feature
// edge or corner, all its tetrahedra in one subdomain) for local improvement.
//
// The vertex climbs the smallest dihedral angle of its star: from its
// position and from the centroid of its neighbours, steps along the gradient
// of its worst tetrahedron's angle (finite differences) with a halving line
// search. A position is kept only when every tetrahedron of the star stays
// positively oriented (CGAL's exact predicate) and the star's smallest angle
// strictly rises. The star's boundary does not move, so the region it tiles
// (and its volume) is the same.
#pragma once

#include <cmath>
#include <utility>
#include <vector>

#include "tet_topology.h"

namespace rdmesh::detail {

/// The tetrahedra around one vertex and its slot in each, for trial positions
/// of that vertex (the other vertices' positions come from the topology).
class Star {
 public:
  /// The alive tetrahedra of vertex v.
  Star(const TetTopology& topo, int v);
  /// Tetrahedra not in the topology yet, the moving vertex at tets[i][slots[i]].
  Star(const TetTopology& topo, std::vector<Tet> tets, std::vector<int> slots)
      : topo_(topo), tets_(std::move(tets)), slot_(std::move(slots)) {}

  /// Smallest dihedral angle of tetrahedron i with the vertex at p.
  double quality(std::size_t i, const Point3& p) const;
  /// The star's smallest angle with the vertex at p, or -1 when it is not
  /// above `floor` or some tetrahedron is not positively oriented.
  double min_quality(const Point3& p, double floor) const;
  /// A direction that raises every tetrahedron within 1 degree of the worst
  /// at p: the point of the convex hull of their gradients nearest to the
  /// origin (Frank-Wolfe). Zero when p is stationary.
  Point3 ascent(const Point3& p, double h) const;

 private:
  /// Gradient of tetrahedron i's smallest angle at p (central differences, step h).
  Point3 gradient(std::size_t i, const Point3& p, double h) const;

  const TetTopology& topo_;
  std::vector<Tet> tets_;
  std::vector<int> slot_;
};

/// The search under every climb: up to kClimbSteps steps from `at` (the
/// caller's position, which `take` moves) along the star's ascent direction
/// there, passed through `direction` (into a tangent plane, say), each the
/// first of kClimbHalvings halvings of 0.2 `nearest` that `take(p)` accepts;
/// it stops when none is.
constexpr int kClimbSteps = 8, kClimbHalvings = 10;
template <class Direction, class Take>
void ascend(const Star& star, const Point3& at, double nearest, Direction direction, Take take) {
  for (int it = 0; it < kClimbSteps; ++it) {
    const Point3 g = direction(star.ascent(at, 1e-4 * nearest));
    const double len = norm(g);
    if (!(len > 0) || !std::isfinite(len)) break;
    const Point3 dir = (1.0 / len) * g;
    double step = 0.2 * nearest;
    bool moved = false;
    for (int k = 0; k < kClimbHalvings && !moved; ++k, step *= 0.5) moved = take(at + step * dir);
    if (!moved) break;
  }
}

/// Climbs the star's smallest angle from `at` (where it is q, every
/// tetrahedron positive), by steps of at most 0.2 `nearest`; moves `at` and
/// returns the angle reached.
double climb(const Star& star, Point3& at, double q, double nearest);

/// Moves free vertex v to raise the smallest dihedral angle of its
/// tetrahedra; true when it moved.
bool smooth_vertex(TetTopology& topo, int v);

}  // namespace rdmesh::detail
