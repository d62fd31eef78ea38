// Criteria refused up front (issue 23): no termination proof, sizes below the
// minimum size, size fields not positive everywhere, absurd element estimates.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rdmesh/criteria.h"
#include "rdmesh/errors.h"

namespace rdmesh {
namespace {

const Box3 kUnit{{0, 0, 0}, {1, 1, 1}};

Criteria uniform(double h) {
  Criteria c = default_criteria(kUnit);
  c.edge_size = c.facet_size = c.cell_size = ScalarField::uniform(h);
  c.facet_distance = h / 10;
  return c;
}

/// The message of check_feasible's InputError, "" when the criteria pass.
std::string refusal(const Criteria& c, double max_elements = kDefaultMaxElements) {
  try {
    check_feasible(c, kUnit, 0.0, max_elements);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CriteriaLimits, TerminationBoundsOfThePaper) {
  Criteria c = uniform(0.1);
  c.cell_radius_edge = 2.0;
  c.facet_angle_deg = 30.0;
  EXPECT_EQ(refusal(c), "");
  c.cell_radius_edge = 1.99;
  EXPECT_NE(refusal(c).find("radius-edge bound 1.99 is below 2"), std::string::npos);
  c.cell_radius_edge = 2.0;
  c.facet_angle_deg = 30.5;
  EXPECT_NE(refusal(c).find("(0, 30]"), std::string::npos) << refusal(c);
}

TEST(CriteriaLimits, MinimumSizeIsResolvedFromTheBox) {
  Criteria c = uniform(0.1);
  EXPECT_DOUBLE_EQ(c.min_size_for(kUnit), 1e-4 * std::sqrt(3.0));
  c.min_size = 0.002;
  EXPECT_EQ(c.min_size_for(kUnit), 0.002);
}

TEST(CriteriaLimits, SizesBelowTheMinimumSizeAreRefusedAndPrintedWithG) {
  Criteria c = uniform(1e-9);
  EXPECT_NE(refusal(c).find("edge size 1e-09 is below the minimum size 0.000173205"),
            std::string::npos)
      << refusal(c);
  c = uniform(0.1);
  c.facet_distance = 1e-300;
  EXPECT_NE(refusal(c).find("facet distance 1e-300 is below"), std::string::npos) << refusal(c);
}

TEST(CriteriaLimits, VaryingSizeMustBePositiveAtEverySampleIncludingCorners) {
  Criteria c = uniform(0.1);
  c.cell_size = ScalarField{0, [](const Point3& p) { return 0.3 - p.x; }};
  EXPECT_NE(refusal(c).find("cell size is -0.0333333 at (0.333333, 0, 0)"), std::string::npos)
      << refusal(c);
  // Only the corner (1, 1, 1) is bad: the corners are samples.
  c.cell_size = ScalarField{0, [](const Point3& p) { return p.x + p.y + p.z < 3 ? 0.1 : NAN; }};
  EXPECT_NE(refusal(c).find("is nan at (1, 1, 1)"), std::string::npos) << refusal(c);
}

TEST(CriteriaLimits, EstimateFollowsTheDocumentedFormula) {
  const ElementEstimate n = estimate_elements(uniform(0.1), kUnit, 2.0);
  EXPECT_NEAR(n.tetrahedra, 5 * 1 / 1e-3, 1e-6);
  // facet size min(0.1, sqrt(sqrt(3) * 0.01)) = 0.1 over the box area 6.
  EXPECT_NEAR(n.triangles, 2 * 6 / 1e-2, 1e-6);
  EXPECT_NEAR(n.edges, 2.0 / 0.1, 1e-9);
  // A size twice as fine in half of the box: the mean of 1/h^3 over the samples.
  Criteria graded = uniform(0.1);
  graded.cell_size = ScalarField{0, [](const Point3& p) { return p.x < 0.5 ? 0.05 : 0.1; }};
  EXPECT_NEAR(estimate_elements(graded, kUnit, 0).tetrahedra, 5 * (0.5 * 8e3 + 0.5 * 1e3), 1e-6);
}

TEST(CriteriaLimits, EstimateAboveTheLimitIsRefusedWithTheWayToRaiseIt) {
  EXPECT_EQ(refusal(uniform(0.01)), "");  // 5e6 tetrahedra
  const std::string m = refusal(uniform(0.002));
  EXPECT_NE(m.find("about 6.28e+08 elements (6.25e+08 tetrahedra, 3e+06 boundary"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("limit of 5e+07"), std::string::npos) << m;
  EXPECT_NE(m.find("--max-elements"), std::string::npos) << m;
  EXPECT_EQ(refusal(uniform(0.002), 1e9), "");
}

}  // namespace
}  // namespace rdmesh
