// Exact circumcenters (and orthocenters of weighted points) for nearly flat
// tetrahedra, where the double formulas of simplex_geometry.h lose their digits. Kept in its own translation unit: the
// exact kernel is slow to compile and only rarely called.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "simplex_geometry.h"

namespace rdmesh::detail {
namespace {

/// Exactly coplanar: decided by Epick's filtered predicate on the doubles
/// themselves, without building the exact kernel's lazy (allocated) points.
/// Flat cells are common (four vertices on one planar face of a triangle
/// mesh), and their centre is at infinity.
bool flat(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  using K = CGAL::Epick;
  const auto p = [](const Point3& q) { return K::Point_3(q.x, q.y, q.z); };
  return CGAL::coplanar(p(a), p(b), p(c), p(d));
}

}  // namespace

Point3 exact_tet_circumcenter(Point3 a, Point3 b, Point3 c, Point3 d) {
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  const auto p = [](Point3 q) { return EK::Point_3(q.x, q.y, q.z); };
  if (flat(a, b, c, d)) {
    const double inf = std::numeric_limits<double>::infinity();
    return {inf, inf, inf};
  }
  const EK::Point_3 center = CGAL::circumcenter(p(a), p(b), p(c), p(d));
  return {CGAL::to_double(center.x()), CGAL::to_double(center.y()), CGAL::to_double(center.z())};
}

Point3 exact_tet_orthocenter(const std::array<Point3, 4>& p, const std::array<double, 4>& w) {
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  const auto wp = [&](int i) { return EK::Weighted_point_3(EK::Point_3(p[i].x, p[i].y, p[i].z), w[i]); };
  if (flat(p[0], p[1], p[2], p[3])) {
    const double inf = std::numeric_limits<double>::infinity();
    return {inf, inf, inf};
  }
  const EK::Point_3 z = CGAL::weighted_circumcenter(wp(0), wp(1), wp(2), wp(3));
  return {CGAL::to_double(z.x()), CGAL::to_double(z.y()), CGAL::to_double(z.z())};
}

}  // namespace rdmesh::detail
