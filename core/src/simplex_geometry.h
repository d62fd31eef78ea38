// Private to core/: inexact constructions on plain points (circumcenters,
// radii). Decisions never rest on them alone: every orientation and
// in-sphere decision goes through CGAL's exact predicates.
#pragma once

#include <algorithm>
#include <array>
#include <limits>

#include "rdmesh/geometry.h"

namespace rdmesh::detail {

/// Orthocenter (weighted circumcenter) of a nearly flat weighted tetrahedron,
/// accurate where the double formula is not (exact_circumcenter.cpp): zero
/// weights give the circumcenter; infinite coordinates for a flat tetrahedron.
Point3 exact_tet_orthocenter(const std::array<Point3, 4>& p, const std::array<double, 4>& w);

/// Circumcenter of tetrahedron abcd: the double formula, or the exact
/// construction when the tetrahedron is so flat that the formula is unreliable
/// (|det| below 1e-6 of the product of the edge lengths from a). Callers treat
/// non-finite centers as "outside".
inline Point3 tet_circumcenter(Point3 a, Point3 b, Point3 c, Point3 d) {
  const Point3 u = b - a, v = c - a, w = d - a;
  const double uu = squared_norm(u), vv = squared_norm(v), ww = squared_norm(w);
  const Point3 vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
  const double det = dot(u, vw);
  if (det * det <= 1e-12 * uu * vv * ww) return exact_tet_orthocenter({a, b, c, d}, {0, 0, 0, 0});
  const Point3 num = uu * vw + vv * wu + ww * uv;
  return a + (0.5 / det) * num;
}

/// Orthocenter of tetrahedron p with weights w: the point of equal power
/// |z - p_i|^2 - w_i to its four vertices (the circumcenter when all weights
/// are zero). Same stability rule as tet_circumcenter.
inline Point3 tet_orthocenter(const std::array<Point3, 4>& p, const std::array<double, 4>& w) {
  if (w[0] == 0 && w[1] == 0 && w[2] == 0 && w[3] == 0) {
    return tet_circumcenter(p[0], p[1], p[2], p[3]);
  }
  const Point3 u = p[1] - p[0], v = p[2] - p[0], x = p[3] - p[0];
  const double uu = squared_norm(u), vv = squared_norm(v), xx = squared_norm(x);
  const Point3 vx = cross(v, x), xu = cross(x, u), uv = cross(u, v);
  const double det = dot(u, vx);
  if (det * det <= 1e-12 * uu * vv * xx) return exact_tet_orthocenter(p, w);
  const double b0 = uu - w[1] + w[0], b1 = vv - w[2] + w[0], b2 = xx - w[3] + w[0];
  return p[0] + (0.5 / det) * (b0 * vx + b1 * xu + b2 * uv);
}

/// Orthocenter of triangle abc with weights wa, wb, wc, in its plane: the
/// foot of the triangle's dual power line (its circumcenter for zero weights).
inline Point3 triangle_orthocenter(Point3 a, double wa, Point3 b, double wb, Point3 c, double wc) {
  const Point3 u = b - a, v = c - a;
  const double uu = squared_norm(u), uv = dot(u, v), vv = squared_norm(v);
  const double bu = 0.5 * (uu - wb + wa), bv = 0.5 * (vv - wc + wa);
  const double det = uu * vv - uv * uv;
  const double alpha = (bu * vv - bv * uv) / det, beta = (bv * uu - bu * uv) / det;
  return a + alpha * u + beta * v;
}

/// Circumcenter of triangle abc (in its plane).
inline Point3 triangle_circumcenter(Point3 a, Point3 b, Point3 c) {
  const Point3 u = b - a, v = c - a;
  const Point3 n = cross(u, v);
  const double nn = squared_norm(n);
  const Point3 num = squared_norm(u) * cross(v, n) + squared_norm(v) * cross(n, u);
  return a + (1.0 / (2.0 * nn)) * num;
}

/// Squared distance from x to segment [a, b].
inline double squared_distance_to_segment(Point3 x, Point3 a, Point3 b) {
  const Point3 ab = b - a;
  const double len2 = squared_norm(ab);
  const double s = len2 > 0 ? std::clamp(dot(x - a, ab) / len2, 0.0, 1.0) : 0.0;
  return squared_norm(a + s * ab - x);
}

inline double min_squared_edge(Point3 a, Point3 b, Point3 c) {
  return std::min({squared_norm(b - a), squared_norm(c - a), squared_norm(c - b)});
}

inline double min_squared_edge(Point3 a, Point3 b, Point3 c, Point3 d) {
  return std::min(
      {min_squared_edge(a, b, c), squared_norm(d - a), squared_norm(d - b), squared_norm(d - c)});
}

}  // namespace rdmesh::detail
