// The core's own walks through the triangulation (triangulation_walks.h)
// promise CGAL's results in CGAL's order, since every later choice (cell
// creation order, hence the output bytes) follows that order: checked against
// Triangulation_3::incident_cells and Regular_triangulation_3::find_conflicts
// on a weighted random triangulation, including the flags they leave behind.
#include "triangulation_walks.h"

#include <gtest/gtest.h>

#include <iterator>
#include <random>
#include <vector>

namespace rdmesh::detail {
namespace {

Weighted_point random_point(std::mt19937& rng, double max_weight) {
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0), weight(0.0, max_weight);
  // Drawn in this order whatever the compiler (the order in which a call's
  // arguments are evaluated is unspecified: GCC's, right to left, here).
  const double w = weight(rng), z = coordinate(rng), y = coordinate(rng), x = coordinate(rng);
  return Weighted_point(Kernel::Point_3(x, y, z), w);
}

/// A regular triangulation of 3000 random points with small random weights.
Triangulation random_triangulation(std::mt19937& rng) {
  Triangulation tr;
  for (int i = 0; i < 3000; ++i) tr.insert(random_point(rng, 1e-3));
  return tr;
}

void expect_all_flags_clear(const Triangulation& tr) {
  for (auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c)
    ASSERT_TRUE(c->tds_data().is_clear());
}

TEST(TriangulationWalks, StarWalkListsCgalsIncidentCellsInTheirOrder) {
  std::mt19937 rng(35);
  const Triangulation tr = random_triangulation(rng);
  ASSERT_EQ(tr.dimension(), 3);
  StarWalk walk;
  std::vector<Cell_handle> ours, cgal;
  std::size_t vertices = 0;
  for (auto v = tr.all_vertices_begin(); v != tr.all_vertices_end(); ++v) {
    walk.cells(v, ours);
    cgal.clear();
    tr.incident_cells(v, std::back_inserter(cgal));
    ASSERT_EQ(ours, cgal) << "vertex " << vertices;
    ++vertices;
  }
  EXPECT_EQ(vertices, tr.number_of_vertices() + 1);  // the infinite vertex too
  expect_all_flags_clear(tr);
}

TEST(TriangulationWalks, ConflictWalkListsCgalsZoneAndBoundaryInTheirOrder) {
  std::mt19937 rng(2026);
  const Triangulation tr = random_triangulation(rng);
  ConflictWalk walk;
  std::vector<Cell_handle> ours, cgal;
  std::vector<Triangulation::Facet> our_boundary, cgal_boundary;
  int zones = 0, outside = 0;
  for (int i = 0; i < 2000; ++i) {
    // Points inside the hull and beyond it, some heavy enough to hide vertices.
    Weighted_point p = random_point(rng, i % 4 == 0 ? 0.05 : 1e-3);
    if (i % 5 == 0)
      p = Weighted_point(Kernel::Point_3(1.5 * p.x(), 1.5 * p.y(), 1.5 * p.z()), p.weight());
    const Cell_handle start = tr.locate(p);
    walk.zone(tr, p, start, ours, our_boundary);
    cgal.clear();
    cgal_boundary.clear();
    tr.find_conflicts(p, start, std::back_inserter(cgal_boundary), std::back_inserter(cgal));
    ASSERT_EQ(ours, cgal) << "point " << i;
    ASSERT_EQ(our_boundary, cgal_boundary) << "point " << i;
    (ours.empty() ? outside : zones)++;
  }
  // Not in conflict with its start cell (a point hidden by a heavier vertex): both empty.
  const Cell_handle start = tr.locate(random_point(rng, 0.0));
  const Weighted_point hidden(start->vertex(0)->point().point(), -1.0);
  if (!tr.is_infinite(start->vertex(0))) {
    walk.zone(tr, hidden, start, ours, our_boundary);
    EXPECT_TRUE(ours.empty());
    EXPECT_TRUE(our_boundary.empty());
  }
  EXPECT_GT(zones, 1500);
  expect_all_flags_clear(tr);
}

TEST(TriangulationWalks, ConflictWalkIfStopsAtTheFirstCellRefusedAndLeavesNoMark) {
  std::mt19937 rng(19);
  const Triangulation tr = random_triangulation(rng);
  ConflictWalk walk;
  std::vector<Cell_handle> all, some;
  std::vector<Triangulation::Facet> all_boundary, some_boundary;
  int refused = 0, accepted = 0;
  for (int i = 0; i < 1000; ++i) {
    const Weighted_point p = random_point(rng, 0.0);
    const Cell_handle start = tr.locate(p);
    walk.zone(tr, p, start, all, all_boundary);
    // Accepting every cell: zone() itself.
    ASSERT_TRUE(walk.zone_if(tr, p, start, some, some_boundary, [](Cell_handle) { return true; }));
    ASSERT_EQ(some, all);
    ASSERT_EQ(some_boundary, all_boundary);
    // Refusing the cells on one side of a plane: true exactly when the zone
    // and every cell next to it lie on the other side, then the same zone.
    auto below = [&](Cell_handle c) {
      for (int k = 0; k < 4; ++k)
        if (tr.is_infinite(c->vertex(k)) || c->vertex(k)->point().x() >= 0.2) return false;
      return true;
    };
    bool all_below = below(start);
    for (const Cell_handle& c : all) all_below = all_below && below(c);
    for (const auto& f : all_boundary) all_below = all_below && below(f.first->neighbor(f.second));
    const bool ok = walk.zone_if(tr, p, start, some, some_boundary, below);
    ASSERT_EQ(ok, all_below) << "point " << i;
    if (ok) {
      ASSERT_EQ(some, all);
      ASSERT_EQ(some_boundary, all_boundary);
    }
    for (const Cell_handle& c : some) ASSERT_TRUE(below(c));  // never past a refused cell
    (ok ? accepted : refused)++;
    expect_all_flags_clear(tr);
  }
  EXPECT_GT(refused, 100);
  EXPECT_GT(accepted, 100);
}

}  // namespace
}  // namespace rdmesh::detail
