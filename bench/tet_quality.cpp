#include "tet_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rdmesh_bench {
namespace {

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

constexpr double kPi = 3.14159265358979323846;

}  // namespace

TetShape tet_shape(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 p[4] = {a, b, c, d};
  TetShape s;
  s.min_dihedral_deg = 180;
  s.max_dihedral_deg = 0;
  // Dihedral angle at edge (i, j): angle between the half-planes through the
  // edge containing k and l. cross(e, u) and cross(e, v) are those half-planes'
  // in-plane directions perpendicular to e, rotated by the same quarter turn.
  static constexpr int kEdges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                       {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  double shortest2 = std::numeric_limits<double>::infinity();
  for (const auto& ed : kEdges) {
    const Vec3 e = sub(p[ed[1]], p[ed[0]]);
    shortest2 = std::min(shortest2, dot(e, e));
    const Vec3 n1 = cross(e, sub(p[ed[2]], p[ed[0]]));
    const Vec3 n2 = cross(e, sub(p[ed[3]], p[ed[0]]));
    const double angle = std::atan2(norm(cross(n1, n2)), dot(n1, n2)) * 180.0 / kPi;
    s.min_dihedral_deg = std::min(s.min_dihedral_deg, angle);
    s.max_dihedral_deg = std::max(s.max_dihedral_deg, angle);
  }
  // Circumcenter relative to a: (|u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v)) / (2 u.(v x w)).
  const Vec3 u = sub(b, a), v = sub(c, a), w = sub(d, a);
  const Vec3 vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
  const double det = 2.0 * dot(u, vw);
  s.signed_volume = det / 12.0;
  if (det == 0.0 || shortest2 == 0.0) {
    s.radius_edge = std::numeric_limits<double>::infinity();
    return s;
  }
  const double uu = dot(u, u), vv = dot(v, v), ww = dot(w, w);
  const Vec3 center = {(uu * vw[0] + vv * wu[0] + ww * uv[0]) / det,
                       (uu * vw[1] + vv * wu[1] + ww * uv[1]) / det,
                       (uu * vw[2] + vv * wu[2] + ww * uv[2]) / det};
  s.radius_edge = norm(center) / std::sqrt(shortest2);
  return s;
}

MeshQuality mesh_quality(const std::vector<Vec3>& vertices, const std::vector<Tet>& tets) {
  MeshQuality q;
  q.tets = tets.size();
  for (const Tet& t : tets) {
    const TetShape s = tet_shape(vertices[t[0]], vertices[t[1]], vertices[t[2]], vertices[t[3]]);
    q.min_dihedral_deg = std::min(q.min_dihedral_deg, s.min_dihedral_deg);
    q.max_dihedral_deg = std::max(q.max_dihedral_deg, s.max_dihedral_deg);
    q.max_radius_edge = std::max(q.max_radius_edge, s.radius_edge);
    q.volume += std::abs(s.signed_volume);
    if (s.signed_volume <= 0) ++q.non_positive;
    if (s.min_dihedral_deg < 10) ++q.below_10_deg;
  }
  return q;
}

}  // namespace rdmesh_bench
