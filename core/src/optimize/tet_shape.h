// Private to core/: the shape measure the optimizers maximize, the smallest
// dihedral angle of a tetrahedron. It is computed in doubles: it ranks
// candidate configurations, it never decides validity (orientation and
// power tests are CGAL's exact predicates).
#pragma once

#include <algorithm>
#include <cmath>

#include "rdmesh/geometry.h"
#include "rdmesh/optimization.h"
#include "rdmesh/portable_math.h"

namespace rdmesh::detail {

/// Cosine of the smallest dihedral angle of tetrahedron p0p1p2p3: larger is
/// worse (1 for a flat or degenerate tetrahedron). Independent of orientation.
inline double max_dihedral_cosine(const Point3& p0, const Point3& p1, const Point3& p2,
                                  const Point3& p3) {
  const Point3 p[4] = {p0, p1, p2, p3};
  Point3 n[4];
  double len[4], side[4];
  int surest = 0;
  for (int k = 0; k < 4; ++k) {
    const Point3& a = p[(k + 1) & 3];
    n[k] = cross(p[(k + 2) & 3] - a, p[(k + 3) & 3] - a);
    len[k] = norm(n[k]);
    if (!(len[k] > 0)) return 1.0;
    side[k] = dot(n[k], p[k] - a);
    if (std::abs(side[k]) > std::abs(side[surest])) surest = k;
  }
  // Outward normals: away from the opposite vertex. side[k] is (-1)^(k+1)
  // times six times the signed volume, so one sign serves all four faces; it
  // is read off the largest of them. (Deciding each face on its own turns
  // some normals of a nearly flat tet inward, and its zero angles then read
  // as large ones.) A flat tet has the worst shape.
  if (!(std::abs(side[surest]) > 0)) return 1.0;
  const bool positive = (surest & 1) ? side[surest] > 0 : side[surest] < 0;
  for (int k = 0; k < 4; ++k)
    if ((k & 1) ? positive : !positive) n[k] = -1.0 * n[k];
  // The dihedral angle between faces k and l satisfies cos = -n_k . n_l (outward unit normals).
  double worst = -1.0;
  for (int k = 0; k < 4; ++k)
    for (int l = k + 1; l < 4; ++l) worst = std::max(worst, -dot(n[k], n[l]) / (len[k] * len[l]));
  return std::min(worst, 1.0);
}

/// The angle in degrees whose cosine is `c` (c from max_dihedral_cosine): the
/// same bits on every machine, since the improvement ranks tetrahedra by it.
inline double cosine_to_degrees(double c) {
  return portable_acos(std::clamp(c, -1.0, 1.0)) * (180.0 / M_PI);
}

/// Adds one tetrahedron of smallest dihedral angle `deg` to `h`.
inline void add_to_histogram(DihedralHistogram& h, double deg) {
  const int bucket = std::clamp(static_cast<int>(deg / 5.0), 0, static_cast<int>(h.size()) - 1);
  ++h[static_cast<std::size_t>(bucket)];
}

}  // namespace rdmesh::detail
