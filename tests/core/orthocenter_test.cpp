// Orthocenters of nearly flat tetrahedra (simplex_geometry.h): the refiner's
// cells on planar patches are often within rounding of flat. Checked against
// CGAL's exact rational construction.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "simplex_geometry.h"

namespace rdmesh::detail {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;

Point3 exact(const std::array<Point3, 4>& p, const std::array<double, 4>& w) {
  const auto wp = [&](int i) {
    return EK::Weighted_point_3(EK::Point_3(p[i].x, p[i].y, p[i].z), w[i]);
  };
  const EK::Point_3 z = CGAL::weighted_circumcenter(wp(0), wp(1), wp(2), wp(3));
  // exact(): to_double of a lazy number may round its interval (1e-5 relative).
  return {CGAL::to_double(z.x().exact()), CGAL::to_double(z.y().exact()),
          CGAL::to_double(z.z().exact())};
}

// A triangle and a fourth point `lift` off its plane (0: in the plane up to the
// rounding of its coordinates), weights up to `weight` times the edge squared.
std::array<Point3, 4> near_flat(std::mt19937& rng, double lift, Point3& normal) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Point3 o{3 + u(rng), -2 + u(rng), 5 + u(rng)};
  const Point3 a = o + Point3{u(rng), u(rng), u(rng)}, b = o + Point3{u(rng), u(rng), u(rng)},
               c = o + Point3{u(rng), u(rng), u(rng)};
  normal = cross(b - a, c - a);
  normal = (1 / norm(normal)) * normal;
  const double s = 0.5 + 0.5 * u(rng), t = 0.5 + 0.5 * u(rng);
  const Point3 d = a + s * (b - a) + t * (c - a) - 0.8 * (s + t) * (b - a) + lift * normal;
  return {a, b, c, d};
}

TEST(Orthocenter, NearlyFlatCellsMatchTheExactCenter) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int compared = 0;
  for (double lift : {1e-3, 1e-6, 1e-9, 1e-12, 1e-14, 0.0}) {
    for (int i = 0; i < 200; ++i) {
      Point3 n;
      const std::array<Point3, 4> p = near_flat(rng, lift, n);
      const bool weighted = i % 2 == 1;
      const std::array<double, 4> w = weighted ? std::array<double, 4>{0.01 * u(rng), 0.01 * u(rng),
                                                                       0.01 * u(rng), 0.01 * u(rng)}
                                               : std::array<double, 4>{0, 0, 0, 0};
      const Point3 z = tet_orthocenter(p, w);
      if (CGAL::coplanar(EK::Point_3(p[0].x, p[0].y, p[0].z), EK::Point_3(p[1].x, p[1].y, p[1].z),
                         EK::Point_3(p[2].x, p[2].y, p[2].z),
                         EK::Point_3(p[3].x, p[3].y, p[3].z))) {
        EXPECT_FALSE(std::isfinite(z.x)) << "a flat cell has its center at infinity";
        continue;
      }
      const Point3 e = exact(p, w);
      // Good to 1e-9 of the center's distance from the cell (the double
      // formula's own accuracy at its threshold is about 1e-10).
      const double scale = std::max(1.0, distance(e, p[0]));
      EXPECT_LE(distance(z, e), 1e-9 * scale) << "lift " << lift << " case " << i;
      ++compared;
    }
  }
  EXPECT_GT(compared, 900);
}

TEST(Orthocenter, CircumcenterOfANearlyFlatCellMatchesTheExactOne) {
  std::mt19937 rng(11);
  for (double lift : {1e-8, 1e-11, 1e-13}) {
    for (int i = 0; i < 100; ++i) {
      Point3 n;
      const std::array<Point3, 4> p = near_flat(rng, lift, n);
      const Point3 z = tet_circumcenter(p[0], p[1], p[2], p[3]);
      const Point3 e = exact(p, {0, 0, 0, 0});
      EXPECT_LE(distance(z, e), 1e-9 * std::max(1.0, distance(e, p[0]))) << lift << " " << i;
    }
  }
}

}  // namespace
}  // namespace rdmesh::detail
