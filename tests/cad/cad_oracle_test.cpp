// The CAD oracle on models built with OpenCASCADE: structure (subdomains,
// patches, curves, corners) and the shared oracle conformance suite.
#include "rdmesh/cad_oracle.h"

#include <gtest/gtest.h>

#include "oracles/oracle_conformance.h"

namespace rdmesh {
namespace {

struct Expected {
  CadTestShape shape;
  const char* name;
  int subdomains, patches, curves, corners;
};

class CadShapes : public ::testing::TestWithParam<Expected> {};

TEST_P(CadShapes, StructureMatchesTheBRep) {
  const Expected e = GetParam();
  const auto oracle = make_cad_test_oracle(e.shape);
  EXPECT_EQ(static_cast<int>(oracle->subdomains().size()), e.subdomains);
  EXPECT_EQ(static_cast<int>(oracle->patches().size()), e.patches);
  EXPECT_EQ(static_cast<int>(oracle->curves().size()), e.curves);
  EXPECT_EQ(static_cast<int>(oracle->corners().size()), e.corners);
}

TEST_P(CadShapes, PassesOracleConformance) {
  const auto oracle = make_cad_test_oracle(GetParam().shape);
  expect_oracle_conformance(*oracle, 400);
}

// Seam edges (cylinder side, sphere) and degenerated edges (sphere poles) are not curves.
INSTANTIATE_TEST_SUITE_P(
    Occt, CadShapes,
    ::testing::Values(Expected{CadTestShape::box, "box", 1, 6, 12, 8},
                      Expected{CadTestShape::cylinder, "cylinder", 1, 3, 2, 0},
                      Expected{CadTestShape::box_minus_cylinder, "box_minus_cylinder", 1, 7, 14, 8},
                      Expected{CadTestShape::two_boxes, "two_boxes", 2, 11, 20, 12},
                      Expected{CadTestShape::sphere, "sphere", 1, 1, 0, 0}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(CadOracle, TwoBoxesShareAnInterfacePatch) {
  const auto oracle = make_cad_test_oracle(CadTestShape::two_boxes);
  int interfaces = 0;
  for (const PatchInfo& p : oracle->patches()) {
    if (p.side_a.value == 1 && p.side_b.value == 2) ++interfaces;
  }
  EXPECT_EQ(interfaces, 1);
  EXPECT_EQ(oracle->locate({5, 5, 5}).value, 1);
  EXPECT_EQ(oracle->locate({15, 5, 5}).value, 2);
  EXPECT_EQ(oracle->locate({25, 5, 5}).value, 0);
  const auto hit = oracle->intersect({5, 5, 5}, {15, 5, 5});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.x, 10, 1e-9);
  EXPECT_NEAR(oracle->exact_volume(), 2000, 1e-6);
}

}  // namespace
}  // namespace rdmesh
