// Sizes per entity on the analytic capped cylinder: parsing by id and name,
// the graded field (the asked size on the entity, growing by grade - 1 per
// unit of distance, the base size far away), and what a mesh achieves on the
// entity against the rest.
#include "rdmesh/entity_sizes.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/capped_cylinder_oracle.h"
#include "core/test_domains.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesher.h"

namespace rdmesh {
namespace {

TEST(EntitySizes, ParsesIdsNamesAndKinds) {
  const test::CappedCylinderOracle o(0.5, 0.6);
  const EntitySize a = parse_entity_size("face:2=0.05", o);
  EXPECT_EQ(a.kind, EntitySize::Kind::kPatch);
  EXPECT_EQ(a.id, 2);
  EXPECT_EQ(a.size, 0.05);
  EXPECT_EQ(a.label, "face:2");
  EXPECT_EQ(parse_entity_size("patch:bottom=1", o).id, 3);
  const EntitySize c = parse_entity_size("curve:\"top rim\"=0.02", o);
  EXPECT_EQ(c.kind, EntitySize::Kind::kCurve);
  EXPECT_EQ(c.id, 1);
  EXPECT_EQ(parse_entity_size("solid:1=0.1", o).kind, EntitySize::Kind::kSubdomain);
  for (const char* bad : {"face:9=0.1", "face:side", "volume:1=0.1", "face:1=-1", "face:1=x",
                          "face:1=0.1x", "curve:rim=0.1", "face:1=nan"}) {
    EXPECT_THROW(parse_entity_size(bad, o), InputError) << bad;
  }
}

TEST(EntitySizes, GradedFromTheEntityAndBaseFarAway) {
  const test::CappedCylinderOracle o(0.5, 0.6);
  Criteria c = test::uniform_criteria(0.2);
  apply_entity_sizes(o, {parse_entity_size("face:1=0.02", o)}, 1.5, c);
  // Graded over read-only data: the refinement may call them from two threads.
  EXPECT_TRUE(c.cell_size.is_concurrent());
  EXPECT_TRUE(c.facet_size.is_concurrent());
  EXPECT_TRUE(c.edge_size.is_concurrent());
  // On the side (radius 0.5): the asked size, up to the facets' sag.
  for (double t : {0.1, 1.7, 4.0}) {
    const Point3 on{0.5 * std::cos(t), 0.5 * std::sin(t), 0.2};
    EXPECT_NEAR(c.cell_size(on), 0.02, 0.002) << t;
    EXPECT_NEAR(c.facet_size(on), 0.02, 0.002) << t;
    // d inside: 0.02 + 0.5 d, until the base size 0.2.
    for (double d : {0.05, 0.1, 0.2}) {
      const Point3 in{(0.5 - d) * std::cos(t), (0.5 - d) * std::sin(t), 0.2};
      EXPECT_NEAR(c.cell_size(in), 0.02 + 0.5 * d, 0.002) << t << " " << d;
    }
  }
  EXPECT_EQ(c.cell_size({0, 0, 0.2}), 0.2);  // 0.5 from the side: 0.27 > 0.2
  EXPECT_THROW(apply_entity_sizes(o, {parse_entity_size("face:1=0.02", o)}, 1.0, c), InputError);
  Criteria tiny = test::uniform_criteria(0.2);
  tiny.min_size = 0.01;
  EXPECT_THROW(apply_entity_sizes(o, {parse_entity_size("face:1=0.005", o)}, 1.4, tiny),
               InputError);
}

TEST(EntitySizes, MeshFollowsTheSizesOnFaceCurveAndSolid) {
  const test::CappedCylinderOracle o(0.5, 0.6);
  const Criteria base = test::uniform_criteria(0.2);
  const std::vector<EntitySize> asked{parse_entity_size("face:top=0.04", o),
                                      parse_entity_size("curve:2=0.03", o)};
  Criteria c = base;
  apply_entity_sizes(o, asked, 1.4, c);
  const TetMesh fine = generate_mesh(o, c).mesh;
  const TetMesh coarse = generate_mesh(o, base).mesh;
  const auto got = achieved_sizes(fine, asked);
  const auto before = achieved_sizes(coarse, asked);
  ASSERT_EQ(got.size(), 2u);
  // Sizes are Delaunay-ball radii: edges are at most about twice as long.
  EXPECT_LE(got[0].mean_edge, 2 * 0.04);
  EXPECT_LE(got[1].max_edge, 2 * 0.03);
  EXPECT_GT(got[0].edges, 3 * before[0].edges);
  EXPECT_LT(got[0].mean_edge, 0.5 * before[0].mean_edge);
  // The bottom cap (patch 3) was not asked for: its edges stay long away
  // from the refined rim.
  const auto bottom = achieved_sizes(fine, {parse_entity_size("face:3=1", o)});
  EXPECT_GT(bottom[0].max_edge, 3 * got[0].mean_edge);

  Criteria s = base;
  apply_entity_sizes(o, {parse_entity_size("solid:1=0.08", o)}, 1.4, s);
  const auto solid =
      achieved_sizes(generate_mesh(o, s).mesh, {parse_entity_size("solid:1=0.08", o)});
  EXPECT_LE(solid[0].mean_edge, 2 * 0.08);
}

}  // namespace
}  // namespace rdmesh
