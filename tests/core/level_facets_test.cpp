// The facet level (rules R3 and R4, level_facets.h) on TinyComplex: each rule
// is reported by name, with the ratio computed here from the geometry.
#include "level_facets.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tiny_complex.h"

namespace rdmesh::detail {
namespace {

// The surface ball of a hull facet: centre n = (+-1, +-1, +-1) / sqrt(3), its
// squared radius the squared distance from n to a vertex, e.g. (1, 0, 0).
const double kBallR2 = 2 - 2 / std::sqrt(3.0);
// The facet's circumcenter is n / sqrt(3): its squared distance to the centre.
const double kDistance2 = (1 - 1 / std::sqrt(3.0)) * (1 - 1 / std::sqrt(3.0));

TEST(FacetLevel, TheEightHullFacetsAreRestrictedWithTheirSurfaceBalls) {
  test::TinyComplex tiny(true);
  const auto facets = tiny.restricted_facets();
  ASSERT_EQ(facets.size(), 8u);
  for (const auto& [c, i] : facets) {
    const Point3 center = c->info().surface_center[i];
    EXPECT_NEAR(norm(center), 1.0, 1e-8);
    EXPECT_NEAR(std::abs(center.x), 1 / std::sqrt(3.0), 1e-8);
    EXPECT_NEAR(tiny.complex.facet_power(c, i, center), kBallR2, 1e-8);
  }
}

TEST(FacetLevel, AFacetWithAVertexOffThePatchViolatesR3) {
  test::TinyComplex tiny(false);
  const Criteria criteria = test::lenient_criteria();
  const FacetLevel level(tiny.complex, criteria);
  test::expect_all(tiny.violations(level), Rule::kR3NotFaithful, kTopologicalPriority, 0);
}

TEST(FacetLevel, FacetsOnThePatchWithinTheCriteriaViolateNothing) {
  test::TinyComplex tiny(true);
  const Criteria criteria = test::lenient_criteria();
  FacetLevel level(tiny.complex, criteria);
  for (const auto& [c, i] : tiny.restricted_facets()) {
    EXPECT_EQ(level.violation(c, i).rule, Rule::kNone);
    level.consider(c, i);
  }
  EXPECT_TRUE(level.empty());
  // A facet not in D|S (an inner one) has no violation either.
  const Cell_handle c = tiny.restricted_facets().front().first;
  for (int i = 0; i < 4; ++i) {
    if (c->info().facet_patch[i] == kNotRestricted) {
      EXPECT_FALSE(level.violation(c, i));
    }
  }
}

TEST(FacetLevel, ASurfaceBallLargerThanTheFacetSizeViolatesR41) {
  test::TinyComplex tiny(true);
  Criteria criteria = test::lenient_criteria();
  criteria.facet_size = ScalarField::uniform(0.5);
  const FacetLevel level(tiny.complex, criteria);
  test::expect_all(tiny.violations(level), Rule::kR4Size, kBallR2 / 0.25, 1e-7);
}

TEST(FacetLevel, AFacetAngleBelowTheBoundViolatesR42) {
  // The facets are equilateral: their smallest angle is 60 degrees, and
  // min edge^2 = 3 R^2 against 4 sin^2(angle) R^2.
  test::TinyComplex tiny(true);
  Criteria criteria = test::lenient_criteria();
  criteria.facet_angle_deg = 59;
  test::expect_all(tiny.violations(FacetLevel(tiny.complex, criteria)), Rule::kNone, 0, 0);
  criteria.facet_angle_deg = 61;
  const double s = std::sin(61 * M_PI / 180);
  test::expect_all(tiny.violations(FacetLevel(tiny.complex, criteria)), Rule::kR4Shape,
                   4 * s * s / 3, 1e-12);
}

TEST(FacetLevel, AFacetFarFromItsBallCentreViolatesTheDistanceAndTheWorstRuleIsReported) {
  test::TinyComplex tiny(true);
  Criteria criteria = test::lenient_criteria();
  criteria.facet_distance = ScalarField::uniform(0.1);
  criteria.facet_size = ScalarField::uniform(0.5);  // R4.1 by 3.4, less than the distance's 17.9
  const FacetLevel level(tiny.complex, criteria);
  test::expect_all(tiny.violations(level), Rule::kR4Distance, kDistance2 / 0.01, 1e-6);
}

TEST(FacetLevel, TheQueuePopsTheWorstLiveFacetAndDropsDestroyedOnes) {
  test::TinyComplex tiny(true);
  Criteria criteria = test::lenient_criteria();
  criteria.facet_size = ScalarField::uniform(0.5);
  FacetLevel level(tiny.complex, criteria);
  const auto facets = tiny.restricted_facets();
  for (const auto& [c, i] : facets) level.consider(c, i);
  ASSERT_EQ(level.size(), 8u);
  // Destroying a facet's cell makes its entry stale.
  tiny.complex.kill(facets.front().first->info());
  std::size_t popped = 0, stale = 0;
  while (!level.empty()) {
    const std::optional<ElementEntry> e = level.pop();
    if (!e) {
      ++stale;
      continue;
    }
    ++popped;
    EXPECT_NE(e->cell->info().facet_patch[e->facet], kNotRestricted);
    EXPECT_NEAR(e->priority, kBallR2 / 0.25, 1e-7);
  }
  EXPECT_EQ(popped, 7u);
  EXPECT_EQ(stale, 1u);
}

}  // namespace
}  // namespace rdmesh::detail
