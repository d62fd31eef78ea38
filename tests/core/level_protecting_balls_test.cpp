// The protecting balls as the curve level (ProtectingBallsLevel,
// level_curves.h) on the capped cylinder r < 1, |z| < 1: its balls go in as
// weighted points whose chains are the rims' D|L, it never refines, and it
// keeps every refinement point out of the balls.
#include <gtest/gtest.h>

#include <cmath>

#include "capped_cylinder_oracle.h"
#include "level_curves.h"
#include "protection.h"
#include "test_domains.h"

namespace rdmesh::detail {
namespace {

struct ProtectedRims {
  ProtectedRims() {
    criteria.min_size = criteria.min_size_for(oracle.bounding_box());
    std::vector<ProtectedCurve> protected_curves;
    for (const CurveInfo& info : oracle.curves()) {
      protected_curves.push_back({info, &oracle.curve(info.id)});
    }
    plan =
        ProtectionPlanner(protected_curves, oracle.corners(), criteria, criteria.min_size, &oracle)
            .plan();
    complex.set_feature_patches(curves.corner_patches(), curves.curve_patches());
    Deadline no_deadline;
    level.insert_initial_points(no_deadline, stats);
    complex.init_unstamped_cells();
  }

  test::CappedCylinderOracle oracle{1.0, 1.0};
  Criteria criteria = test::uniform_criteria(0.3);
  ProtectionPlan plan;
  RefinementStats stats;
  RestrictedComplex complex{oracle, false};
  RestrictedCurves curves{oracle};
  ProtectingBallsLevel level{plan, curves, complex, oracle, criteria};
};

TEST(ProtectingBallsLevel, TheBallsAreTheRimsSamplesAsWeightedVertices) {
  ProtectedRims rims;
  ASSERT_GT(rims.plan.balls, 10u);
  EXPECT_EQ(rims.stats.initial_points, rims.plan.balls);
  EXPECT_EQ(rims.complex.triangulation().number_of_vertices(), rims.plan.balls);
  for (std::size_t j = 0; j < 2; ++j) {
    const CurveState& c = rims.curves.curves()[j];
    const std::vector<BallSample>& balls = rims.plan.curves[j].samples;
    // A closed rim carries its first ball twice, at both ends of its range.
    ASSERT_EQ(c.samples.size(), balls.size());
    EXPECT_EQ(c.samples.begin()->second.vertex, std::prev(c.samples.end())->second.vertex);
    std::size_t i = 0;
    for (const auto& [t, sample] : c.samples) {
      const BallSample& b = balls[i++];
      EXPECT_EQ(t, b.t);
      EXPECT_EQ(sample.position, b.point);
      EXPECT_EQ(sample.vertex->point().weight(), b.radius * b.radius);
      EXPECT_EQ(sample.vertex->info().dim(), FeatureDim::kCurve);
      EXPECT_NEAR(std::hypot(b.point.x, b.point.y), 1.0, 1e-9);
    }
  }
}

TEST(ProtectingBallsLevel, NeverRefinesAndKeepsPointsOutOfTheBalls) {
  ProtectedRims rims;
  rims.level.queue_initial_arcs();
  EXPECT_TRUE(rims.level.empty());
  EXPECT_EQ(rims.level.size(), 0u);
  Insertion insertion(rims.complex, rims.curves, rims.criteria.min_size, rims.stats);
  EXPECT_FALSE(rims.level.refine_next(insertion));
  const BallSample& ball = rims.plan.curves[0].samples[1];
  // Inside a ball, next to its centre: kept out of P_0, and no arc refined instead.
  const Point3 inside{ball.point.x * (1 - 0.5 * ball.radius),
                      ball.point.y * (1 - 0.5 * ball.radius), ball.point.z};
  EXPECT_TRUE(rims.level.keeps_out(inside, Cell_handle()));
  EXPECT_FALSE(rims.level.refine_encroached(inside, insertion).has_value());
  EXPECT_FALSE(rims.level.keeps_out({0, 0, 0}, Cell_handle()));
  // A cell whose orthosphere has no positive radius lies inside the balls.
  const Triangulation& tr = rims.complex.triangulation();
  std::size_t inside_balls = 0, outside_balls = 0;
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
    const bool kept = rims.level.keeps_cell_centre(c);
    EXPECT_EQ(kept, !(c->info().squared_radius > 0));
    (kept ? inside_balls : outside_balls) += 1;
  }
  EXPECT_GT(outside_balls, 0u);
  EXPECT_FALSE(rims.level.has_conflicts());
}

}  // namespace
}  // namespace rdmesh::detail
