// Curvature of CAD models through OpenCASCADE: closed forms on the test
// shapes, GeomLProp on a shared torus, and sizes by curvature on a shared
// part with a cylinder (radius 5 mm): every edge of its circles at most
// 2 pi R / N, and far fewer elements than a uniform mesh at that size.
#include <gtest/gtest.h>

#include <cmath>

#include "rdmesh/cad_oracle.h"
#include "rdmesh/curvature_sizes.h"
#include "rdmesh/entity_sizes.h"
#include "rdmesh/mesher.h"
#include "shared_data.h"

namespace rdmesh {
namespace {

TEST(CurvatureCad, TestShapesInClosedForm) {
  const auto cylinder = make_cad_test_oracle(CadTestShape::cylinder);  // radius 5
  bool side = false;
  for (const PatchInfo& p : cylinder->patches()) {
    for (const Point3& x : cylinder->initial_points(p.id)) {
      const auto k = cylinder->curvature(x, p.id);
      ASSERT_TRUE(k.has_value());
      const bool curved = std::hypot(x.x, x.y) > 4.999;
      side = side || curved;
      EXPECT_NEAR(*k, curved ? 0.2 : 0.0, 1e-12);
    }
  }
  EXPECT_TRUE(side);
  for (const CurveInfo& c : cylinder->curves()) {  // the two rims
    EXPECT_NEAR(cylinder->curve(c.id).curvature(0.5 * (c.t_begin + c.t_end)), 0.2, 1e-9);
  }
  const auto sphere = make_cad_test_oracle(CadTestShape::sphere);  // radius 10
  EXPECT_NEAR(*sphere->curvature({0, 0, 10}, PatchId(1)), 0.1, 1e-12);
}

TEST(CurvatureCad, TorusThroughGeomLProp) {
  RDMESH_REQUIRE_SHARED_DATA(path, "step/gmsh_torus_step_header_data.stp");
  const auto oracle = load_cad_file(path);
  // One toroidal face: its minor radius is 2 V / A (V = 2 pi^2 R r^2, A = 4 pi^2 R r),
  // and the largest principal curvature is 1 / r everywhere on it.
  ASSERT_EQ(oracle->patches().size(), 1u);
  const double r = 2 * oracle->exact_volume() / oracle->exact_area();
  int samples = 0;
  for (const Point3& x : oracle->initial_points(PatchId(1))) {
    const auto k = oracle->curvature(x, PatchId(1));
    ASSERT_TRUE(k.has_value());
    EXPECT_NEAR(*k, 1 / r, 1e-6 / r);
    ++samples;
  }
  EXPECT_GT(samples, 2);
}

TEST(CurvatureCad, CylinderPartGetsNEdgesPerTurn) {
  RDMESH_REQUIRE_SHARED_DATA(path, "step/cadquery_red_cube_blue_cylinder.step");
  const auto oracle = load_cad_file(path);
  const Criteria base = default_criteria(oracle->bounding_box());
  Criteria c = base;
  SizeRequests asked;
  asked.curvature = 32;
  const SizesApplied applied = apply_sizes(*oracle, asked, c);
  EXPECT_NEAR(applied.curvature.min_radius, 5.0, 1e-6);
  EXPECT_EQ(applied.curvature.clamped, 0u);
  const double target = 2 * M_PI * 5 / 32;  // longest edge on the cylinder
  ASSERT_LT(0.5 * target, base.facet_size(oracle->bounding_box().center()));
  const TetMesh mesh = generate_mesh(*oracle, c).mesh;
  const CurvatureAchieved got =
      achieved_curvature(mesh, *oracle, 32, c.min_size_for(oracle->bounding_box()));
  std::printf("curve edges %zu (max %.3f of 2 pi R / N), facets %zu (max %.3f, mean %.3f)\n",
              got.curve_edges, got.curve_max_ratio, got.facets, got.facet_max_ratio,
              got.facet_mean_ratio);
  ASSERT_GE(got.curve_edges, 2u * 32u);  // two circles of radius 5
  EXPECT_LE(got.curve_max_ratio, 1.0);
  EXPECT_LT(got.facet_mean_ratio, 1.0);
  EXPECT_LE(got.facet_max_ratio, 2.0);  // the documented bound next to the rims' protecting balls
  // A uniform mesh at the cylinder's size has far more tetrahedra.
  Criteria uniform = base;
  uniform.edge_size = uniform.facet_size = uniform.cell_size = 0.5 * target;
  const TetMesh fine = generate_mesh(*oracle, uniform).mesh;
  std::printf("tetrahedra: curvature %zu, uniform %zu\n", mesh.tets.size(), fine.tets.size());
  EXPECT_LT(3 * mesh.tets.size(), fine.tets.size());
}

}  // namespace
}  // namespace rdmesh
