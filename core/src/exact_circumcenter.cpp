// Exact circumcenters for nearly flat tetrahedra, where the double formula of
// simplex_geometry.h loses its digits. Kept in its own translation unit: the
// exact kernel is slow to compile and only rarely called.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "simplex_geometry.h"

namespace rdmesh::detail {

Point3 exact_tet_circumcenter(Point3 a, Point3 b, Point3 c, Point3 d) {
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  const auto p = [](Point3 q) { return EK::Point_3(q.x, q.y, q.z); };
  if (CGAL::coplanar(p(a), p(b), p(c), p(d))) {
    const double inf = std::numeric_limits<double>::infinity();
    return {inf, inf, inf};
  }
  const EK::Point_3 center = CGAL::circumcenter(p(a), p(b), p(c), p(d));
  return {CGAL::to_double(center.x()), CGAL::to_double(center.y()), CGAL::to_double(center.z())};
}

}  // namespace rdmesh::detail
