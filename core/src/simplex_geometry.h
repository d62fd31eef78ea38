// Private to core/: inexact constructions on plain points (circumcenters,
// radii). Decisions never rest on them alone: every orientation and
// in-sphere decision goes through CGAL's exact predicates.
#pragma once

#include <algorithm>
#include <limits>

#include "rdmesh/geometry.h"

namespace rdmesh::detail {

/// Circumcenter of tetrahedron abcd computed exactly and rounded (exact_circumcenter.cpp);
/// infinite coordinates for a flat tetrahedron.
Point3 exact_tet_circumcenter(Point3 a, Point3 b, Point3 c, Point3 d);

/// Circumcenter of tetrahedron abcd: the double formula, or the exact
/// construction when the tetrahedron is so flat that the formula is unreliable
/// (|det| below 1e-6 of the product of the edge lengths from a). Callers treat
/// non-finite centers as "outside".
inline Point3 tet_circumcenter(Point3 a, Point3 b, Point3 c, Point3 d) {
  const Point3 u = b - a, v = c - a, w = d - a;
  const double uu = squared_norm(u), vv = squared_norm(v), ww = squared_norm(w);
  const Point3 vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
  const double det = dot(u, vw);
  if (det * det <= 1e-12 * uu * vv * ww) return exact_tet_circumcenter(a, b, c, d);
  const Point3 num = uu * vw + vv * wu + ww * uv;
  return a + (0.5 / det) * num;
}

/// Circumcenter of triangle abc (in its plane).
inline Point3 triangle_circumcenter(Point3 a, Point3 b, Point3 c) {
  const Point3 u = b - a, v = c - a;
  const Point3 n = cross(u, v);
  const double nn = squared_norm(n);
  const Point3 num = squared_norm(u) * cross(v, n) + squared_norm(v) * cross(n, u);
  return a + (1.0 / (2.0 * nn)) * num;
}

inline double min_squared_edge(Point3 a, Point3 b, Point3 c) {
  return std::min({squared_norm(b - a), squared_norm(c - a), squared_norm(c - b)});
}

inline double min_squared_edge(Point3 a, Point3 b, Point3 c, Point3 d) {
  return std::min({min_squared_edge(a, b, c), squared_norm(d - a), squared_norm(d - b),
                   squared_norm(d - c)});
}

}  // namespace rdmesh::detail
