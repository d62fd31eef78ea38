// Surface-only meshing (MeshOptions::surface_only): an open triangle-mesh
// surface and a closed implicit one meshed without volume. Checked: no
// tetrahedra, the Euler characteristic of the input, every output vertex on the
// surface, facets within the facet distance, a consistent orientation, the
// border made of the border curves' feature edges, each curve one chain.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "mesh_checks.h"
#include "rdmesh/mesh_measures.h"
#include "rdmesh/mesher.h"
#include "rdmesh/triangle_mesh_oracle.h"
#include "test_domains.h"

namespace rdmesh {
namespace {

/// z = 0.1 sin(3x) cos(2y) over [0, 1]^2, a 24 x 24 grid: a wavy disk.
TriangleSoup wavy_sheet() {
  TriangleSoup s;
  const int n = 24;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n;
      s.points.push_back({x, y, 0.1 * std::sin(3 * x) * std::cos(2 * y)});
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      s.triangles.push_back({a, b, d});
      s.triangles.push_back({a, d, c});
    }
  }
  return s;
}

/// Each edge used by two triangles is traversed once in each direction; the
/// edges used once are returned (the border), sorted.
std::set<std::pair<int, int>> expect_oriented(const std::vector<std::array<int, 3>>& triangles) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  std::set<std::pair<int, int>> border;
  for (const auto& [e, count] : directed) {
    EXPECT_EQ(count, 1) << "edge " << e.first << "-" << e.second << " used twice the same way";
    if (!directed.count({e.second, e.first})) border.insert(std::minmax(e.first, e.second));
  }
  return border;
}

TEST(SurfaceOnly, OpenWavySheet) {
  const TriangleMeshOracle oracle(wavy_sheet(), "wavy", {.surface_only = true});
  const Criteria criteria = test::uniform_criteria(0.08);
  MeshOptions options;
  options.surface_only = true;
  const MeshResult result = generate_mesh(oracle, criteria, options);
  const TetMesh& mesh = result.mesh;
  EXPECT_TRUE(mesh.tets.empty());
  ASSERT_GT(mesh.triangles.size(), 50u);
  EXPECT_FALSE(result.stats.guard_fired());
  EXPECT_FALSE(result.exudation.ran);
  EXPECT_EQ(euler_characteristic(mesh.triangles), 1) << "a disk";
  EXPECT_EQ(test::connected_components(mesh.triangles), 1);
  // Vertices on the input surface; facet centroids within 1.5 facet distances.
  for (const Point3& v : mesh.vertices) {
    const auto q = oracle.project(v, PatchId{1});
    ASSERT_TRUE(q.has_value());
    EXPECT_LE(distance(*q, v), 1e-9);
  }
  for (const auto& t : mesh.triangles) {
    const Point3 g = (1.0 / 3) * (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]);
    EXPECT_LE(distance(*oracle.project(g, PatchId{1}), g), 1.5 * criteria.facet_distance.constant);
  }
  // Consistently oriented; the border is exactly the border curves' edges,
  // each curve one open chain between its corners.
  const std::set<std::pair<int, int>> border = expect_oriented(mesh.triangles);
  std::set<std::pair<int, int>> feature;
  for (const auto& e : mesh.edges) feature.insert(std::minmax(e[0], e[1]));
  EXPECT_EQ(border, feature);
  ASSERT_EQ(mesh.curves.size(), 4u) << "four sides between four corners";
  for (const CurveInfo& c : mesh.curves) {
    std::size_t count = 0;
    const std::map<int, int> degree = test::curve_degrees(mesh, c.id, count);
    EXPECT_EQ(degree.size(), count + 1) << c.name << ": not one chain";
  }
  EXPECT_EQ(mesh.corner_vertices.size(), 4u);
}

TEST(SurfaceOnly, ClosedImplicitSphereNeedsNoLabels) {
  const ImplicitOracle sphere = test::unit_sphere();
  MeshOptions options;
  options.surface_only = true;
  const MeshResult result = generate_mesh(sphere, test::uniform_criteria(0.2), options);
  EXPECT_TRUE(result.mesh.tets.empty());
  EXPECT_EQ(euler_characteristic(result.mesh.triangles), 2);
  expect_oriented(result.mesh.triangles);
  for (const Point3& v : result.mesh.vertices) EXPECT_NEAR(norm(v), 1.0, 1e-8);
  // Closed pieces come out oriented outward: positive enclosed volume.
  double volume = 0;
  for (const auto& t : result.mesh.triangles) {
    const Point3 &a = result.mesh.vertices[t[0]], &b = result.mesh.vertices[t[1]],
                 &c = result.mesh.vertices[t[2]];
    volume += dot(a, cross(b, c)) / 6;
  }
  EXPECT_NEAR(volume, 4.0 / 3.0 * M_PI, 0.05 * 4.0 / 3.0 * M_PI);
}

}  // namespace
}  // namespace rdmesh
