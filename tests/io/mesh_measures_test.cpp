// Geometric helpers on tetrahedra with known answers, and topology of known surfaces.
#include "rdmesh/mesh_measures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "io/test_meshes.h"

namespace rdmesh {
namespace {

// Regular tetrahedron with edge length 2*sqrt(2), positively oriented.
const Point3 kA{1, 1, 1}, kB{1, -1, -1}, kC{-1, -1, 1}, kD{-1, 1, -1};

double deg(double rad) { return rad * 180.0 / std::numbers::pi; }

TEST(MeshMeasures, RegularTetrahedron) {
  ASSERT_GT(signed_volume(kA, kB, kC, kD), 0);
  EXPECT_NEAR(signed_volume(kA, kB, kC, kD), std::pow(2 * std::sqrt(2.0), 3) / (6 * std::sqrt(2.0)),
              1e-14);
  const std::vector<double> angles = dihedral_angles_deg(kA, kB, kC, kD);
  ASSERT_EQ(angles.size(), 6u);
  for (double a : angles) EXPECT_NEAR(a, deg(std::acos(1.0 / 3.0)), 1e-12);
  EXPECT_NEAR(deg(std::acos(1.0 / 3.0)), 70.528779, 1e-6);
  EXPECT_NEAR(radius_edge_ratio(kA, kB, kC, kD), std::sqrt(6.0) / 4.0, 1e-14);
}

TEST(MeshMeasures, RightCornerTetrahedron) {
  const Point3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  EXPECT_DOUBLE_EQ(signed_volume(o, x, y, z), 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(signed_volume(o, y, x, z), -1.0 / 6.0);  // swapping two vertices flips the sign
  // Edges o-x, o-y, o-z: right angles; x-y, x-z, y-z: acos(1/sqrt(3)) = 54.7356 deg.
  const std::vector<double> a = dihedral_angles_deg(o, x, y, z);
  EXPECT_NEAR(a[0], 90, 1e-12);
  EXPECT_NEAR(a[1], 90, 1e-12);
  EXPECT_NEAR(a[2], 90, 1e-12);
  for (int i = 3; i < 6; ++i) EXPECT_NEAR(a[i], deg(std::acos(1 / std::sqrt(3.0))), 1e-12);
  // Circumcentre (1/2, 1/2, 1/2), radius sqrt(3)/2; shortest edge 1.
  EXPECT_NEAR(radius_edge_ratio(o, x, y, z), std::sqrt(3.0) / 2.0, 1e-14);
}

TEST(MeshMeasures, DihedralAnglesFollowTheDocumentedEdgeOrder) {
  const Point3 o{0, 0, 0}, x{2, 0, 0}, y{0, 1, 0}, z{0.3, 0.2, 1.5};
  const std::vector<double> a = dihedral_angles_deg(o, x, y, z);
  const std::vector<double> b = dihedral_angles_deg(x, o, z, y);  // edges: xo, xz, xy, oz, oy, zy
  EXPECT_NEAR(b[0], a[0], 1e-12);
  EXPECT_NEAR(b[1], a[4], 1e-12);
  EXPECT_NEAR(b[2], a[3], 1e-12);
  EXPECT_NEAR(b[3], a[2], 1e-12);
  EXPECT_NEAR(b[4], a[1], 1e-12);
  EXPECT_NEAR(b[5], a[5], 1e-12);
}

TEST(MeshMeasures, FlatTetrahedron) {
  // Four coplanar points (a square): zero volume, angles 0 or 180, infinite radius-edge.
  const Point3 a{0, 0, 0}, b{1, 0, 0}, c{1, 1, 0}, d{0, 1, 0};
  EXPECT_EQ(signed_volume(a, b, c, d), 0.0);
  for (double angle : dihedral_angles_deg(a, b, c, d)) {
    EXPECT_TRUE(std::abs(angle) < 1e-12 || std::abs(angle - 180) < 1e-12) << angle;
  }
  EXPECT_EQ(radius_edge_ratio(a, b, c, d), std::numeric_limits<double>::infinity());
}

TEST(MeshMeasures, SliverHasSmallAndLargeAngles) {
  // A square with two opposite corners lifted slightly: the classic sliver.
  const double h = 1e-3;
  const Point3 a{0, 0, 0}, b{1, 0, h}, c{1, 1, 0}, d{0, 1, h};
  const std::vector<double> angles = dihedral_angles_deg(a, b, c, d);
  EXPECT_LT(*std::min_element(angles.begin(), angles.end()), 1.0);
  EXPECT_GT(*std::max_element(angles.begin(), angles.end()), 179.0);
  // The circumradius stays ~sqrt(2)/2 while the volume vanishes: radius-edge is bounded.
  EXPECT_NEAR(radius_edge_ratio(a, b, c, d), std::sqrt(2.0) / 2.0, 1e-3);
}

TEST(MeshMeasures, ExtremesAreTheSmallestAndLargestOfTheSixAngles) {
  // Random tets (well shaped, slivers, needles), a flat one and one with a
  // degenerate face (a repeated vertex: its angles are reported as 0).
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<std::array<Point3, 4>> tets;
  for (int k = 0; k < 2000; ++k) {
    const double squash = k % 3 == 0 ? 1e-4 : 1.0;  // every third one nearly flat
    std::array<Point3, 4> t;
    for (Point3& p : t) p = {u(rng), u(rng), squash * u(rng)};
    tets.push_back(t);
  }
  tets.push_back({Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{1, 1, 0}, Point3{0, 1, 0}});
  tets.push_back({Point3{0, 0, 0}, Point3{0, 0, 0}, Point3{1, 1, 0}, Point3{0, 1, 1}});
  for (const auto& t : tets) {
    const std::vector<double> all = dihedral_angles_deg(t[0], t[1], t[2], t[3]);
    const auto [lo, hi] = dihedral_extremes_deg(t[0], t[1], t[2], t[3]);
    EXPECT_NEAR(lo, *std::min_element(all.begin(), all.end()), 1e-9);
    EXPECT_NEAR(hi, *std::max_element(all.begin(), all.end()), 1e-9);
  }
  const auto [flat_lo, flat_hi] =
      dihedral_extremes_deg(Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{1, 1, 0}, Point3{0, 1, 0});
  EXPECT_NEAR(flat_lo, 0, 1e-12);
  EXPECT_NEAR(flat_hi, 180, 1e-12);
  EXPECT_EQ(
      dihedral_extremes_deg(Point3{0, 0, 0}, Point3{0, 0, 0}, Point3{1, 1, 0}, Point3{0, 1, 1})
          .first,
      0.0);
}

TEST(MeshMeasures, EulerCharacteristicOfClosedSurfaces) {
  EXPECT_EQ(euler_characteristic(testing::cube_surface_triangles()), 2);
  EXPECT_EQ(euler_characteristic(testing::torus_triangles(5, 4)), 0);
  EXPECT_EQ(euler_characteristic(testing::torus_triangles(12, 7)), 0);
}

TEST(MeshMeasures, EulerCharacteristicOfOpenAndEmptySets) {
  EXPECT_EQ(euler_characteristic({}), 0);
  EXPECT_EQ(euler_characteristic({{7, 8, 9}}), 1);  // unused indices 0..6 do not count
  auto cube = testing::cube_surface_triangles();
  cube.pop_back();
  cube.pop_back();  // remove one square: a disk
  EXPECT_EQ(euler_characteristic(cube), 1);
}

TEST(MeshMeasures, EdgeManifold) {
  EXPECT_TRUE(is_edge_manifold({}));
  EXPECT_TRUE(is_edge_manifold(testing::cube_surface_triangles()));
  EXPECT_TRUE(is_edge_manifold(testing::torus_triangles(4, 3)));

  auto open = testing::cube_surface_triangles();
  open.pop_back();  // a hole: boundary edges used once
  EXPECT_FALSE(is_edge_manifold(open));

  auto fin = testing::cube_surface_triangles();
  fin.push_back({0, 3, 8});  // a fin on the diagonal 0-3: that edge is in 4 triangles
  fin.push_back({0, 8, 3});  // (its other edges are closed off by the twin)
  EXPECT_FALSE(is_edge_manifold(fin));
}

TEST(MeshMeasures, TwoCubeFixtureIsConsistent) {
  const TetMesh m = testing::two_cube_mesh(1.0);
  ASSERT_EQ(m.tets.size(), 12u);
  for (const auto& t : m.tets) {
    EXPECT_GT(signed_volume(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], m.vertices[t[3]]),
              0);
  }
  // Outer skins are disks; together they form the closed box surface.
  EXPECT_EQ(testing::triangles_of(m, 1).size(), 10u);
  EXPECT_EQ(testing::triangles_of(m, 2).size(), 10u);
  EXPECT_EQ(testing::triangles_of(m, 3).size(), 2u);
  auto skin = testing::triangles_of(m, 1);
  auto right = testing::triangles_of(m, 2);
  skin.insert(skin.end(), right.begin(), right.end());
  EXPECT_TRUE(is_edge_manifold(skin));
  EXPECT_EQ(euler_characteristic(skin), 2);
  // Orientation contract: outer normals point away from the box centre, interface towards x < 1.
  const Point3 centre{1, 0.5, 0.5};
  for (std::size_t f = 0; f < m.triangles.size(); ++f) {
    const auto& t = m.triangles[f];
    const Point3 n =
        cross(m.vertices[t[1]] - m.vertices[t[0]], m.vertices[t[2]] - m.vertices[t[0]]);
    if (m.triangle_patch[f].value == 3) {
      EXPECT_LT(n.x, 0);
    } else {
      EXPECT_GT(dot(n, m.vertices[t[0]] - centre), 0);
    }
  }
}

}  // namespace
}  // namespace rdmesh
