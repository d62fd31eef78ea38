// The CAD oracle on models built with OpenCASCADE: structure (subdomains,
// patches, curves, corners) and the shared oracle conformance suite.
#include "rdmesh/cad_oracle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "oracles/oracle_conformance.h"
#include "rdmesh/errors.h"
#include "same_answers_on_threads.h"
#include "shared_data.h"

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

// An edge's whole length is computed once, when the edge is built: asked over
// its range or any range covering it, the answer is the same number, 2 pi r
// for the cylinder's circles (radius 5), and the sum of its two halves.
TEST(CadOracle, CurveLengthOverTheWholeEdgeIsItsLength) {
  const auto oracle = make_cad_test_oracle(CadTestShape::cylinder);
  ASSERT_EQ(oracle->curves().size(), 2u);
  for (const CurveInfo& c : oracle->curves()) {
    const Curve& curve = oracle->curve(c.id);
    const double whole = curve.length(c.t_begin, c.t_end);
    EXPECT_NEAR(whole, 2 * 3.141592653589793 * 5, 1e-9);
    EXPECT_EQ(curve.length(c.t_begin - 1, c.t_end + 1), whole);
    const double mid = 0.5 * (c.t_begin + c.t_end);
    EXPECT_NEAR(curve.length(c.t_begin, mid) + curve.length(mid, c.t_end), whole, 1e-12 * whole);
    EXPECT_NEAR(curve.length(c.t_begin, mid), 0.5 * whole, 1e-9);
  }
}

// distance_to_other_patches() on the box [0,10] x [0,20] x [0,30]: from
// (5, 10, 1) the bottom face is 1 away, the faces x = 0 and x = 10 are 5 away.
TEST(CadOracle, DistanceToOtherPatchesSkipsTheListedOnes) {
  const auto oracle = make_cad_test_oracle(CadTestShape::box);
  const Point3 p{5, 10, 1};
  std::optional<PatchId> bottom;
  for (const PatchInfo& patch : oracle->patches()) {
    const std::optional<Point3> q = oracle->project(p, patch.id);
    ASSERT_TRUE(q.has_value());
    if (std::fabs(q->z) < 1e-9 && std::fabs(distance(*q, p) - 1) < 1e-9) bottom = patch.id;
  }
  ASSERT_TRUE(bottom.has_value());
  const double tol = 1e-9;
  EXPECT_NEAR(oracle->distance_to_other_patches(p, {}, 8), 1, tol);
  EXPECT_NEAR(oracle->distance_to_other_patches(p, {*bottom}, 8), 5, tol);
  EXPECT_EQ(oracle->distance_to_other_patches(p, {*bottom}, 3), 3) << "nothing within the limit";
  std::vector<PatchId> all;
  for (const PatchInfo& patch : oracle->patches()) all.push_back(patch.id);
  EXPECT_EQ(oracle->distance_to_other_patches(p, all, 8), 8);
  // Closest points on a face's boundary: from outside the box, beyond an edge.
  EXPECT_NEAR(oracle->distance_to_other_patches({-3, 10, -4}, {}, 8), 5, tol);
}

TEST(CadOracle, TwoBoxesShareAnInterfacePatch) {
  const auto oracle = make_cad_test_oracle(CadTestShape::two_boxes);
  int interfaces = 0;
  for (const PatchInfo& p : oracle->patches()) {
    if (p.side_a.value == 1 && p.side_b.value == 2) ++interfaces;
  }
  EXPECT_EQ(interfaces, 1);
  EXPECT_EQ(oracle->locate({5, 5, 5}).label.value, 1);
  EXPECT_EQ(oracle->locate({15, 5, 5}).label.value, 2);
  EXPECT_EQ(oracle->locate({25, 5, 5}).label.value, 0);
  const auto hit = oracle->intersect({5, 5, 5}, {15, 5, 5});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.x, 10, 1e-9);
  EXPECT_NEAR(oracle->exact_volume(), 2000, 1e-6);
}

}  // namespace
}  // namespace rdmesh

namespace rdmesh {
namespace {

// Queries from several threads give the serial answers (per-thread OpenCASCADE state).
TEST(CadOracle, ConcurrentQueriesMatchSerialOnes) {
  const auto oracle = make_cad_test_oracle(CadTestShape::box_minus_cylinder);
  const Box3 box = oracle->bounding_box();
  std::vector<Point3> pts;
  for (int i = 0; i < 400; ++i) {
    const double s = (i * 0.6180339887) - std::floor(i * 0.6180339887);
    const double t = (i * 0.7548776662) - std::floor(i * 0.7548776662);
    const double u = (i * 0.5698402910) - std::floor(i * 0.5698402910);
    pts.push_back({box.lo.x + s * (box.hi.x - box.lo.x), box.lo.y + t * (box.hi.y - box.lo.y),
                   box.lo.z + u * (box.hi.z - box.lo.z)});
  }
  auto answers = [&] {
    std::vector<double> out;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      out.push_back(oracle->locate(pts[i]).label.value);
      const auto hit = oracle->intersect(pts[i], pts[i + 1]);
      out.push_back(hit ? hit->point.x + hit->patch.value : -1.0);
    }
    return out;
  };
  test::expect_same_answers_on_threads(answers, 4);
}

}  // namespace
}  // namespace rdmesh

namespace rdmesh {
namespace {

// The conformance suite on shared STEP files (see shared_data.h when it is absent).
TEST(CadOracle, SharedStepFilesPassConformance) {
  for (const char* f : {"cadquery_red_cube_blue_cylinder.step", "gmsh_torus_step_header_data.stp",
                        "gmsh_box_step_boundary_colors.stp"}) {
    SCOPED_TRACE(f);
    RDMESH_REQUIRE_SHARED_DATA(path, std::string("step/") + f);
    expect_oracle_conformance(*load_cad_file(path), 400);
  }
}

}  // namespace
}  // namespace rdmesh
