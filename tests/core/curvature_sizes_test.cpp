// Sizes by curvature through the library (no CLI): a sizing object parsed and
// resolved, applied to the criteria, a mesh made with them. On the capped
// cylinder (radius 0.5, so pi R / N = 0.098 at N = 16) the sizes follow the
// side and its rims, the flat caps keep the base size away from them, and
// every rim edge is at most 2 pi R / N long.
#include "rdmesh/curvature_sizes.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/capped_cylinder_oracle.h"
#include "core/test_domains.h"
#include "rdmesh/entity_sizes.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesher.h"

namespace rdmesh {
namespace {

TEST(CurvatureSizes, FieldFollowsTheCurvedSideAndGrades) {
  const test::CappedCylinderOracle o(0.5, 0.6);
  Criteria c = test::uniform_criteria(0.3);
  const SizeRequests asked =
      resolve_size_spec(parse_size_spec(R"({"curvature": 16, "grade": 1.5})", "api"), o);
  EXPECT_EQ(asked.curvature, 16);
  EXPECT_EQ(asked.grade, 1.5);
  const SizesApplied applied = apply_sizes(o, asked, c);
  const double target = M_PI * 0.5 / 16;
  EXPECT_NEAR(applied.curvature.min_radius, 0.5, 1e-5);  // rims by finite differences
  EXPECT_EQ(applied.curvature.clamped, 0u);
  EXPECT_EQ(applied.curvature.unknown, 0u);
  EXPECT_GT(applied.curvature.pieces, 0u);
  for (double t : {0.3, 2.0, 5.1}) {
    const Point3 on{0.5 * std::cos(t), 0.5 * std::sin(t), 0.1};
    // The pieces are the first surface mesh's chords, up to its facet
    // distance d = 0.03 off the side, their sizes lowered by 0.5 d: on the
    // side the size is the target within 0.5 d.
    EXPECT_NEAR(c.facet_size(on), target, 0.5 * 0.03 + 1e-9) << t;
    EXPECT_NEAR(c.edge_size({0.5 * std::cos(t), 0.5 * std::sin(t), 0.6}), target, 0.015 + 1e-9);
    // 0.2 inside: graded by 0.5 per unit of distance to the chords.
    const Point3 in{0.3 * std::cos(t), 0.3 * std::sin(t), 0.1};
    EXPECT_GE(c.cell_size(in), target - 0.015 + 0.5 * (0.2 - 0.03) - 1e-9) << t;
    EXPECT_LE(c.cell_size(in), target + 0.5 * 0.2 + 1e-9) << t;
  }
  EXPECT_EQ(c.cell_size({0, 0, 0}), 0.3);  // 0.5 from the side: 0.35 > 0.3
}

TEST(CurvatureSizes, ClampedToTheMinimumSizeAndCounted) {
  const test::CappedCylinderOracle o(0.5, 0.6);
  Criteria c = test::uniform_criteria(0.3);
  c.min_size = 0.05;  // above pi R / 64 = 0.0245
  SizeRequests asked;
  asked.curvature = 64;
  const SizesApplied applied = apply_sizes(o, asked, c);
  EXPECT_GT(applied.curvature.clamped, 0u);
  EXPECT_EQ(applied.curvature.min_size, 0.05);
  EXPECT_GE(c.facet_size({0.5, 0, 0}), 0.05);
  asked.curvature = -1;
  EXPECT_THROW(apply_sizes(o, asked, c), InputError);
}

TEST(CurvatureSizes, MeshHasAtLeastNEdgesPerTurnAndCoarseCaps) {
  const test::CappedCylinderOracle o(0.5, 0.6);
  const Criteria base = test::uniform_criteria(0.3);
  Criteria c = base;
  SizeRequests asked;
  asked.curvature = 16;
  (void)apply_sizes(o, asked, c);
  const TetMesh mesh = generate_mesh(o, c).mesh;
  const CurvatureAchieved got = achieved_curvature(mesh, o, 16, c.min_size_for(o.bounding_box()));
  ASSERT_GT(got.curve_edges, 0u);
  EXPECT_LE(got.curve_max_ratio, 1.0);  // every rim edge <= 2 pi R / 16
  // At least 16 edges on each rim.
  std::size_t rim_edges[3] = {0, 0, 0};
  for (const CurveId& id : mesh.edge_curve) ++rim_edges[id.value];
  EXPECT_GE(rim_edges[1], 16u);
  EXPECT_GE(rim_edges[2], 16u);
  EXPECT_GT(got.facets, 0u);
  EXPECT_LT(got.facet_mean_ratio, 1.0);
  // Compared with a uniform mesh at the curvature size: far fewer cells.
  const TetMesh uniform = generate_mesh(o, test::uniform_criteria(M_PI * 0.5 / 16)).mesh;
  EXPECT_LT(2 * mesh.tets.size(), uniform.tets.size());
}

// The whole pipeline on samples/torus.json (minor radius 0.3, its largest
// curvature everywhere): refinement leaves every boundary edge within
// 2 pi R / N, and neither the exudation nor the final improvement's slides
// along the surface lengthen one past it (without the size check, slides left
// two edges over at N = 12 and at N = 20, up to 1.07 times it at N = 40).
TEST(CurvatureSizes, TheWholePipelineKeepsTheFacetSizes) {
  const ImplicitOracle o({{-1.5, -1.5, -0.5}, {1.5, 1.5, 0.5}}, {[](const Point3& p) {
                           const double q = std::sqrt(p.x * p.x + p.y * p.y) - 1.0;
                           return q * q + p.z * p.z - 0.09;
                         }});
  for (const int per_turn : {12, 20}) {
    SCOPED_TRACE(testing::Message() << per_turn << " per turn");
    Criteria c = test::uniform_criteria(0.3);  // as `rdmesh torus.json --size 0.3 --curvature N`
    c.facet_distance = 0.005;
    c.min_size = 1e-4 * o.bounding_box().diagonal();
    SizeRequests asked;
    asked.curvature = per_turn;
    (void)apply_sizes(o, asked, c);
    const MeshResult r = generate_mesh(o, c);
    EXPECT_GT(r.improvement.boundary_moves, 0u);
    const CurvatureAchieved got =
        achieved_curvature(r.mesh, o, per_turn, c.min_size_for(o.bounding_box()));
    ASSERT_GT(got.facets, 1000u);
    EXPECT_EQ(got.facets_over, 0u);
    EXPECT_LE(got.facet_max_ratio, 1.0);
  }
}

TEST(CurvatureSizes, SizingObjectErrorsNameTheKey) {
  const test::CappedCylinderOracle o(0.5, 0.6);
  for (const char* bad : {R"({"curvature": 0})", R"({"grade": 1})", R"({"face:1": -1})",
                          R"({"bogus": 1})", R"({"face:1": "x"})", R"([1])", "{"}) {
    EXPECT_THROW(parse_size_spec(bad, "s.json"), InputError) << bad;
  }
  try {
    (void)resolve_size_spec(parse_size_spec(R"({"face:9": 0.1})", "s.json"), o);
    ADD_FAILURE() << "no error for an unknown face";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("face:9"), std::string::npos) << e.what();
  }
  const SizeRequests named =
      resolve_size_spec(parse_size_spec(R"({"face:top": 0.1, "curve:\"top rim\"": 0.05})", "s"), o);
  ASSERT_EQ(named.entities.size(), 2u);
  EXPECT_EQ(named.entities[0].id, 2);
  EXPECT_EQ(named.entities[1].kind, EntitySize::Kind::kCurve);
}

}  // namespace
}  // namespace rdmesh
