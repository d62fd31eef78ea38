// The cell level (rule R5, level_cells.h) on TinyComplex: its eight cells have
// squared radius 3/4 and shortest edge 1; each rule is reported by name, with
// the ratio computed here.
#include "level_cells.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tiny_complex.h"

namespace rdmesh::detail {
namespace {

constexpr double kSquaredRadius = 0.75;

TEST(CellLevel, CellsWithinTheCriteriaViolateNothingAndOutsideCellsNeverDo) {
  test::TinyComplex tiny(true);
  Criteria criteria = test::lenient_criteria();
  const Triangulation& tr = tiny.complex.triangulation();
  std::size_t inside = 0;
  {
    const CellLevel level(tiny.complex, criteria);
    for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
      ASSERT_EQ(c->info().label, 1);
      EXPECT_NEAR(c->info().squared_radius, kSquaredRadius, 1e-12);
      EXPECT_FALSE(level.violation(c));
      ++inside;
    }
  }
  EXPECT_EQ(inside, 8u);
  // Tiny sizes: every cell of D|O is bad, the infinite (outside) ones never.
  criteria.cell_size = ScalarField::uniform(1e-3);
  const CellLevel level(tiny.complex, criteria);
  for (auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) {
    EXPECT_EQ(bool(level.violation(c)), !tr.is_infinite(c));
  }
}

TEST(CellLevel, ADelaunayBallLargerThanTheCellSizeViolatesR51) {
  test::TinyComplex tiny(true);
  Criteria criteria = test::lenient_criteria();
  criteria.cell_size = ScalarField::uniform(0.5);
  const CellLevel level(tiny.complex, criteria);
  test::expect_all(tiny.violations(level), Rule::kR5Size, kSquaredRadius / 0.25, 1e-12);
}

TEST(CellLevel, ARadiusEdgeRatioAboveTheBoundViolatesR52) {
  // Radius sqrt(3)/2 over shortest edge 1: 0.866.
  test::TinyComplex tiny(true);
  Criteria criteria = test::lenient_criteria();
  criteria.cell_radius_edge = 0.87;
  test::expect_all(tiny.violations(CellLevel(tiny.complex, criteria)), Rule::kNone, 0, 0);
  criteria.cell_radius_edge = 0.8;
  test::expect_all(tiny.violations(CellLevel(tiny.complex, criteria)), Rule::kR5Shape,
                   kSquaredRadius / 0.64, 1e-12);
}

TEST(CellLevel, BothRulesReportTheWorse) {
  test::TinyComplex tiny(true);
  Criteria criteria = test::lenient_criteria();
  criteria.cell_radius_edge = 0.8;                 // ratio 1.17
  criteria.cell_size = ScalarField::uniform(0.5);  // ratio 3
  const CellLevel level(tiny.complex, criteria);
  test::expect_all(tiny.violations(level), Rule::kR5Size, kSquaredRadius / 0.25, 1e-12);
  criteria.cell_size = ScalarField::uniform(0.85);  // ratio 1.04, less than the shape's 1.17
  test::expect_all(tiny.violations(level), Rule::kR5Shape, kSquaredRadius / 0.64, 1e-12);
}

TEST(CellLevel, TheQueueDropsDestroyedCellsAndCellsNoLongerBad) {
  test::TinyComplex tiny(true);
  Criteria criteria = test::lenient_criteria();
  criteria.cell_size = ScalarField::uniform(0.5);
  CellLevel level(tiny.complex, criteria);
  Triangulation& tr = tiny.complex.triangulation();
  for (auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) level.consider(c);
  ASSERT_EQ(level.size(), 8u);
  tiny.complex.kill(tr.finite_cells_begin()->info());
  criteria.cell_size = ScalarField::uniform(10);  // the level reads the criteria when popping
  std::size_t live = 0;
  while (!level.empty()) live += level.pop().has_value();
  EXPECT_EQ(live, 0u);
}

TEST(CellLevel, QueueBucketsAreFourPerDoublingReadExactly) {
  // bucket_of(p) = floor(4 log2 p), from the exponent and the mantissa, no libm.
  EXPECT_EQ(CellLevel::bucket_of(0.5), 0u);
  EXPECT_EQ(CellLevel::bucket_of(1.0), 0u);
  EXPECT_EQ(CellLevel::bucket_of(std::numeric_limits<double>::quiet_NaN()), 0u);
  for (int k = 0; k < 64; ++k) {
    const double p = std::ldexp(1.0, k);
    if (k > 0) {
      EXPECT_EQ(CellLevel::bucket_of(p), 4u * k) << "2^" << k;
    }
    EXPECT_EQ(CellLevel::bucket_of(std::nextafter(p * 2, 0.0)), 4u * k + 3) << "below 2^" << k + 1;
  }
  // Against floor(4 log2 p) away from the bucket edges, where both must agree.
  for (double p = 1.001; p < 1e18; p *= 1.0137) {
    const double exact = 4 * std::log2(p);
    if (std::abs(exact - std::round(exact)) < 1e-9) continue;
    EXPECT_EQ(CellLevel::bucket_of(p), static_cast<std::size_t>(std::floor(exact))) << p;
  }
  EXPECT_EQ(CellLevel::bucket_of(1e300), 256u);  // the last bucket holds the rest
  EXPECT_EQ(CellLevel::bucket_of(std::numeric_limits<double>::infinity()), 256u);
}

}  // namespace
}  // namespace rdmesh::detail
