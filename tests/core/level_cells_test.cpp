// The cell level (rule R5, level_cells.h) on TinyComplex: its eight cells have
// squared radius 3/4 and shortest edge 1; each rule is reported by name, with
// the ratio computed here.
#include "level_cells.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace rdmesh::detail
