// The exudation's shape measure (core/src/optimize/tet_shape.h): the smallest
// dihedral angle of a tetrahedron, whatever the order of its vertices, and
// the worst for a flat or nearly flat one.
#include "optimize/tet_shape.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace rdmesh::detail {
namespace {

/// Smallest dihedral angle (degrees) of p in every one of the 24 vertex orders.
template <class Check>
void for_every_order(std::array<Point3, 4> p, Check check) {
  std::array<int, 4> order{0, 1, 2, 3};
  do {
    const double deg =
        cosine_to_degrees(max_dihedral_cosine(p[order[0]], p[order[1]], p[order[2]], p[order[3]]));
    SCOPED_TRACE(testing::Message() << "order " << order[0] << order[1] << order[2] << order[3]);
    check(deg);
  } while (std::next_permutation(order.begin(), order.end()));
}

TEST(TetShape, TheSmallestDihedralAngleOfKnownTetrahedra) {
  // Regular: acos(1/3) at every edge.
  const double a = 1 / std::sqrt(2.0);
  for_every_order({Point3{1, 0, -a}, Point3{-1, 0, -a}, Point3{0, 1, a}, Point3{0, -1, a}},
                  [](double deg) { EXPECT_NEAR(deg, std::acos(1.0 / 3) * 180 / M_PI, 1e-9); });
  // The corner of a cube: 90 degrees at the three edges through the origin,
  // acos(1/sqrt(3)) at the three others.
  for_every_order(
      {Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{0, 0, 1}},
      [](double deg) { EXPECT_NEAR(deg, std::acos(1 / std::sqrt(3.0)) * 180 / M_PI, 1e-9); });
}

TEST(TetShape, AFlatOrNearlyFlatTetrahedronHasTheWorstShape) {
  // Exactly flat: a square.
  for_every_order({Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{1, 1, 0}, Point3{0, 1, 0}},
                  [](double deg) { EXPECT_EQ(deg, 0.0); });
  // Four vertices of a refined wedge (samples/wedge.json), two on each of its
  // planes through the axis, at the same two heights: a trapezoid, flat but
  // for rounding (its exact orientation is +4e-23, evaluated in doubles
  // -2e-22). Deciding the outward side of each face on its own turned some
  // normals inward in 8 of the 24 orders, and the tetrahedron then measured
  // 180 degrees: the best shape, which exudation kept in its output.
  for_every_order({Point3{0.05664077140030008, 0.032701564615071295, -0.9978589232386036},
                   Point3{0.0654031292301426, 0.0, -0.9978589232386036},
                   Point3{0.09801714032955988, 0.0, -0.9951847266721969},
                   Point3{0.08488533353170309, 0.049008570164779934, -0.9951847266721969}},
                  [](double deg) { EXPECT_LT(deg, 0.01); });
}

}  // namespace
}  // namespace rdmesh::detail
