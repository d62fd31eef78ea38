// The curve level (level_curves.h) on the capped cylinder r < 1, |z| < 1:
// its two rims are closed curves, each first sampled at t = 0, 2pi/3, 4pi/3.
// An arc of 2pi/3 has its restricted Delaunay ball centred at its middle, on
// the circle, with radius 1 (the chord from the middle to an end), and its
// chord lies 1/2 from that centre. Each rule is reported by name, with the
// ratio computed here; an encroached arc is refined at its ball's centre.
#include "level_curves.h"

#include <gtest/gtest.h>

#include <cmath>

#include "capped_cylinder_oracle.h"
#include "level_facets.h"
#include "test_domains.h"

namespace rdmesh::detail {
namespace {

/// Forwards the insertion's events to the curve level (the refiner's job).
struct ForwardToCurves final : InsertionObserver {
  explicit ForwardToCurves(CurveLevel& level) : level(level) {}
  void zone_found(const std::vector<Cell_handle>& zone) override { level.zone_found(zone); }
  void inserted(Vertex_handle v) override { level.inserted(v); }
  CurveLevel& level;
};

struct Rims {
  explicit Rims(const Criteria& c) : criteria(c) {
    complex.set_feature_patches(curves.corner_patches(), curves.curve_patches());
    Deadline no_deadline;
    level.insert_initial_points(no_deadline, stats);
    complex.init_unstamped_cells();
  }
  /// The arcs of both rims.
  std::vector<std::pair<int, CurveState::Arc>> arcs() {
    std::vector<std::pair<int, CurveState::Arc>> out;
    for (int j = 0; j < 2; ++j) {
      CurveState& c = curves.curves()[j];
      for (auto a = c.samples.begin(); c.has_next(a); ++a) out.emplace_back(j, a);
    }
    return out;
  }

  test::CappedCylinderOracle oracle{1.0, 1.0};
  Criteria criteria;
  RefinementStats stats;
  RestrictedComplex complex{oracle, false};
  RestrictedCurves curves{oracle};
  CurveRefinementLevel level{curves, complex, criteria};
};

Criteria lenient() {
  Criteria c = test::uniform_criteria(10);
  c.facet_distance = ScalarField::uniform(10);
  return c;
}

TEST(CurveLevel, InitialSamplesMakeThreeArcsPerRimWithUnitBalls) {
  Rims rims(lenient());
  EXPECT_EQ(rims.stats.initial_points, 6u);
  ASSERT_EQ(rims.arcs().size(), 6u);
  for (const auto& [j, a] : rims.arcs()) {
    EXPECT_FALSE(rims.level.update_arc(j, a));
    const CurveSample& s = a->second;
    EXPECT_NEAR(s.squared_radius, 1.0, 1e-9);
    EXPECT_NEAR(std::hypot(s.center.x, s.center.y), 1.0, 1e-12);
    EXPECT_NEAR(std::abs(s.center.z), 1.0, 1e-12);
  }
  EXPECT_TRUE(rims.level.empty());
}

TEST(CurveLevel, AnArcBallLargerThanTheEdgeSizeViolatesR2) {
  Criteria c = lenient();
  c.edge_size = ScalarField::uniform(0.5);
  Rims rims(c);
  for (const auto& [j, a] : rims.arcs()) {
    const Violation v = rims.level.update_arc(j, a);
    EXPECT_EQ(v.rule, Rule::kR2Size);
    EXPECT_NEAR(v.priority, 1.0 / 0.25, 1e-8);
  }
  EXPECT_EQ(rims.level.size(), 6u);
}

TEST(CurveLevel, AChordFarFromItsArcViolatesR2sDistanceAndTheWorstRuleIsReported) {
  Criteria c = lenient();
  c.edge_size = ScalarField::uniform(0.5);         // ratio 4
  c.facet_distance = ScalarField::uniform(0.125);  // (1/2)^2 / 0.125^2 = 16
  Rims rims(c);
  for (const auto& [j, a] : rims.arcs()) {
    const Violation v = rims.level.update_arc(j, a);
    EXPECT_EQ(v.rule, Rule::kR2Distance);
    EXPECT_NEAR(v.priority, 16.0, 1e-7);
    EXPECT_EQ(rims.level.violation(j, a).rule, Rule::kR2Distance);
  }
}

TEST(CurveLevel, AVertexInsideAnArcBallViolatesR1) {
  Rims rims(lenient());
  // A volume point 0.1 inside the middle of the first arc of the top rim
  // (t = pi/3): in that arc's ball only.
  const Point3 x{0.9 * std::cos(M_PI / 3), 0.9 * std::sin(M_PI / 3), 1.0};
  rims.complex.triangulation().insert(to_weighted(x));
  int r1 = 0;
  for (const auto& [j, a] : rims.arcs()) {
    const Violation v = rims.level.update_arc(j, a);
    const bool holds_x = squared_norm(x - a->second.center) < a->second.squared_radius;
    EXPECT_EQ(v.rule, holds_x ? Rule::kR1NotRestricted : Rule::kNone);
    if (holds_x) {
      EXPECT_EQ(v.priority, kTopologicalPriority);
      ++r1;
    }
  }
  EXPECT_EQ(r1, 1);
  // The R1 entry stays valid: popping it refines the arc at its ball's centre.
  Insertion insertion(rims.complex, rims.curves, 1e-6, rims.stats);
  ForwardToCurves forward(rims.level);
  insertion.set_observer(&forward);
  ASSERT_EQ(rims.level.size(), 1u);
  EXPECT_TRUE(rims.level.refine_next(insertion));
  EXPECT_EQ(rims.stats.inserted_edge_centers, 1u);
  EXPECT_EQ(rims.curves.curves()[0].samples.size(), 5u);
}

TEST(CurveLevel, APointInsideAnArcBallRefinesThatArcInstead) {
  Rims rims(lenient());
  for (const auto& [j, a] : rims.arcs()) rims.level.update_arc(j, a);
  Insertion insertion(rims.complex, rims.curves, 1e-6, rims.stats);
  ForwardToCurves forward(rims.level);
  insertion.set_observer(&forward);
  // The axis's middle is in no arc's ball (distance sqrt(2) from every centre).
  const Point3 far{0, 0, 0};
  ASSERT_TRUE(
      insertion.find_zone(to_weighted(far), rims.complex.triangulation().locate(to_weighted(far))));
  EXPECT_FALSE(rims.level.refine_encroached(far, insertion).has_value());
  // A facet centre near the top rim's first arc encroaches it: the arc is
  // split at its ball's centre, on the rim, instead.
  const Point3 x{0.8 * std::cos(M_PI / 3), 0.8 * std::sin(M_PI / 3), 0.9};
  ASSERT_TRUE(
      insertion.find_zone(to_weighted(x), rims.complex.triangulation().locate(to_weighted(x))));
  const std::optional<bool> inserted = rims.level.refine_encroached(x, insertion);
  ASSERT_TRUE(inserted.has_value());
  EXPECT_TRUE(*inserted);
  EXPECT_EQ(rims.stats.inserted_edge_centers, 1u);
  const CurveState& top = rims.curves.curves()[0];
  ASSERT_EQ(top.samples.size(), 5u);
  const auto mid = std::next(top.samples.begin());
  EXPECT_NEAR(mid->first, M_PI / 3, 1e-9);
  EXPECT_NEAR(distance(mid->second.position, {0.5, std::sqrt(3.0) / 2, 1.0}), 0.0, 1e-9);
  EXPECT_EQ(mid->second.vertex->info().dim(), FeatureDim::kCurve);
}

}  // namespace
}  // namespace rdmesh::detail
