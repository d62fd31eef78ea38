// Curvature queries of the built-in oracles and curves against closed forms:
// an implicit sphere and torus (finite-difference Hessian), parametric and
// polyline circles and a helix, and the discrete curvature of triangle meshes
// (a sphere tessellated with its vertices on it, the shared flat-faced cube).
#include <gtest/gtest.h>

#include <cmath>

#include "rdmesh/domain_file.h"
#include "rdmesh/implicit_oracle.h"
#include "rdmesh/parametric_curve.h"
#include "rdmesh/polyline_curve.h"
#include "rdmesh/triangle_mesh_oracle.h"
#include "shared_data.h"

namespace rdmesh {
namespace {

TEST(Curvature, ImplicitSphereAndTorus) {
  const LoadedDomain sphere = parse_domain_json(
      R"({"bbox": [-1, -1, -1, 1, 1, 1], "functions": {"s": "x^2 + y^2 + z^2 - 0.25"}})", "s");
  for (const Point3& p : {Point3{0.5, 0, 0}, Point3{0, 0, -0.5}, Point3{0.3, 0.4, 0}}) {
    const auto k = sphere.oracle->curvature(p, PatchId(1));
    ASSERT_TRUE(k.has_value());
    EXPECT_NEAR(*k, 2.0, 1e-4);
  }
  EXPECT_FALSE(sphere.oracle->curvature({0.5, 0, 0}, PatchId(7)).has_value());
  // Torus R = 1, r = 0.3: principal curvatures 1/r and cos(v) / (R + r cos(v)).
  const LoadedDomain torus = parse_domain_json(
      R"({"bbox": [-1.5, -1.5, -0.5, 1.5, 1.5, 0.5],
          "functions": {"t": "(sqrt(x^2 + y^2) - 1)^2 + z^2 - 0.09"}})",
      "t");
  for (double v : {0.0, 1.0, 2.5, M_PI}) {
    const Point3 p{1 + 0.3 * std::cos(v), 0, 0.3 * std::sin(v)};
    const auto k = torus.oracle->curvature(p, PatchId(1));
    ASSERT_TRUE(k.has_value());
    EXPECT_NEAR(*k, 1 / 0.3, 1e-3 / 0.3) << v;
  }
}

TEST(Curvature, ParametricCurves) {
  const ParametricCurve circle("2*cos(t)", "2*sin(t)", "1", 0, 2 * M_PI);
  for (double t : {0.0, 1e-9, 0.7, 3.0, 2 * M_PI}) EXPECT_NEAR(circle.curvature(t), 0.5, 1e-5) << t;
  // Helix (r cos t, r sin t, c t): r / (r^2 + c^2).
  const ParametricCurve helix("cos(t)", "sin(t)", "0.5*t", 0, 10);
  for (double t : {0.0, 2.0, 9.9}) EXPECT_NEAR(helix.curvature(t), 1 / 1.25, 1e-5) << t;
  const ParametricCurve line("t", "2*t", "3", -1, 1);
  EXPECT_NEAR(line.curvature(0.2), 0.0, 1e-6);
}

TEST(Curvature, PolylinesAreDiscreteCircles) {
  std::vector<Point3> ring;
  for (int i = 0; i <= 64; ++i) {
    const double a = 2 * M_PI * (i % 64) / 64;
    ring.push_back({2 * std::cos(a), 2 * std::sin(a), 0});
  }
  const PolylineCurve closed(ring);
  for (double t : {0.0, 0.3, 5.0, closed.t_end()}) EXPECT_NEAR(closed.curvature(t), 0.5, 1e-12);
  ring.pop_back();
  const PolylineCurve open(ring);  // the ends take their neighbours' value
  EXPECT_NEAR(open.curvature(0), 0.5, 1e-12);
  EXPECT_EQ(PolylineCurve({{0, 0, 0}, {1, 0, 0}, {3, 0, 0}}).curvature(0.5), 0.0);
}

/// A sphere of radius r as a UV mesh (n bands) with its vertices on the sphere.
TriangleSoup uv_sphere(double r, int n) {
  TriangleSoup s;
  s.points.push_back({0, 0, r});
  for (int i = 1; i < n; ++i) {
    const double phi = M_PI * i / n;
    for (int j = 0; j < 2 * n; ++j) {
      const double th = M_PI * j / n;
      s.points.push_back(
          {r * std::sin(phi) * std::cos(th), r * std::sin(phi) * std::sin(th), r * std::cos(phi)});
    }
  }
  s.points.push_back({0, 0, -r});
  const int m = 2 * n, last = static_cast<int>(s.points.size()) - 1;
  auto at = [m](int i, int j) { return 1 + (i - 1) * m + (j % m); };
  for (int j = 0; j < m; ++j) {
    s.triangles.push_back({0, at(1, j), at(1, j + 1)});
    s.triangles.push_back({last, at(n - 1, j + 1), at(n - 1, j)});
    for (int i = 1; i + 1 < n; ++i) {
      s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return s;
}

TEST(Curvature, TriangleMeshDiscreteCurvature) {
  const TriangleMeshOracle sphere(uv_sphere(2.0, 24));
  ASSERT_EQ(sphere.patches().size(), 1u);
  for (const Point3& p : {Point3{2, 0, 0}, Point3{0, 1.2, 1.6}, Point3{0, 0, -2}}) {
    const auto k = sphere.curvature(p, PatchId(1));
    ASSERT_TRUE(k.has_value());
    EXPECT_NEAR(*k, 0.5, 0.05) << p.x << " " << p.y << " " << p.z;
  }
  RDMESH_REQUIRE_SHARED_DATA(cube_path, "mesh/cgal_cube.off");
  const auto cube = TriangleMeshOracle::from_file(cube_path);
  for (const PatchInfo& info : cube->patches()) {
    for (const Point3& p : cube->initial_points(info.id)) {
      const auto k = cube->curvature(p, info.id);
      ASSERT_TRUE(k.has_value());
      EXPECT_NEAR(*k, 0.0, 1e-9);
    }
  }
}

}  // namespace
}  // namespace rdmesh
