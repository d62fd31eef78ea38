// ConeBuilder (cone_hole.h): raising a vertex's weight in place must give the
// regular triangulation of the new weighted points, with the same vertex object,
// whether the cone takes its extra cells from the container or from a pool.
// Checked against a triangulation built from scratch.
#include "optimize/cone_hole.h"

#include <gtest/gtest.h>

#include <array>
#include <iterator>
#include <random>
#include <vector>

namespace rdmesh::detail {
namespace {

TEST(ConeHole, RaisingAWeightInPlaceGivesTheRegularTriangulationWithOrWithoutAPool) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Weighted_point> points;
  for (int i = 0; i < 200; ++i) {
    // z, y, x: the same points with any compiler (GCC's order of the arguments
    // in the call this was; the order of a call's arguments is unspecified).
    const double z = u(rng), y = u(rng), x = u(rng);
    points.emplace_back(Kernel::Point_3(x, y, z), 0.0);
  }
  Triangulation tr(points.begin(), points.end());
  ASSERT_EQ(tr.number_of_vertices(), points.size());

  int seen = 0;  // interior vertices passed over: every 7th is raised
  for (int round = 0; round < 26; ++round) {
    // An interior vertex (no infinite cell around it) gets a weight of a fraction
    // of its squared distance to its nearest neighbour: it stays a vertex. The
    // last rounds take a vertex of the infinite vertex's cell, which the cone
    // must then replace.
    Vertex_handle v;
    for (int k = 0; round >= 20 && k < 4; ++k) {
      const Vertex_handle u = tr.infinite_cell()->vertex(k);
      if (!tr.is_infinite(u) && u->point().weight() == 0) v = u;
    }
    for (auto it = tr.finite_vertices_begin(); round < 20 && it != tr.finite_vertices_end(); ++it) {
      std::vector<Cell_handle> star;
      tr.incident_cells(it, std::back_inserter(star));
      bool inner = true;
      for (const Cell_handle& c : star) inner = inner && !tr.is_infinite(c);
      if (inner && it->point().weight() == 0 && (seen++ % 7) == 0) {
        v = it;
        break;
      }
    }
    ASSERT_NE(v, Vertex_handle());
    std::vector<Vertex_handle> adjacent;
    tr.finite_adjacent_vertices(v, std::back_inserter(adjacent));
    double nearest = 1e300;
    for (const Vertex_handle& w : adjacent) {
      nearest = std::min(nearest, CGAL::squared_distance(v->point().point(), w->point().point()));
    }
    const Weighted_point raised_point(v->point().point(), 0.2 * nearest);

    std::vector<Cell_handle> hole;
    std::vector<Triangulation::Facet> boundary;
    tr.find_conflicts(raised_point, v->cell(), std::back_inserter(boundary),
                      std::back_inserter(hole));
    ASSERT_FALSE(hole.empty());
    ASSERT_FALSE(boundary.empty());
    const std::size_t vertices = tr.number_of_vertices();
    // What each new cell must be: the inner cell's vertices, v for the one opposite the facet.
    std::vector<HoleFacet> facets;
    std::vector<std::array<Vertex_handle, 4>> expected;
    for (const Triangulation::Facet& f : boundary) {
      facets.push_back({f.first, f.second});
      std::array<Vertex_handle, 4> q;
      for (int k = 0; k < 4; ++k) q[k] = k == f.second ? v : f.first->vertex(k);
      expected.push_back(q);
    }
    // Odd rounds with a pool of 50 cells, even ones with the container.
    const std::size_t container = tr.tds().cells().size();
    CellPool pool(tr);
    if (round % 2 == 1) pool.fill(50);
    ConeBuilder cone;
    std::vector<Cell_handle> created;
    cone.build(tr, hole, facets, v, round % 2 == 1 ? &pool : nullptr, created);
    v->set_point(raised_point);
    ASSERT_EQ(created.size(), boundary.size());
    for (std::size_t k = 0; k < created.size(); ++k) {
      for (int i = 0; i < 4; ++i) ASSERT_EQ(created[k]->vertex(i), expected[k][i]) << k;
      EXPECT_EQ(created[k]->info().stamp, 0u);  // a fresh info
      if (k < hole.size()) {
        EXPECT_EQ(created[k], hole[k]) << "the hole's cells come first";
      }
    }
    if (round % 2 == 1) {
      // The container did not change: the pool gave and took the difference.
      EXPECT_EQ(tr.tds().cells().size(), container + 50);
      EXPECT_EQ(pool.size() + boundary.size(), 50 + hole.size());
      pool.release();
    }
    EXPECT_EQ(tr.tds().cells().size(), container - hole.size() + boundary.size());

    // The same vertex object, no vertex lost or added, a valid regular triangulation,
    // and one new cell around v per boundary facet of the hole.
    ASSERT_TRUE(tr.is_vertex(v));
    EXPECT_EQ(tr.number_of_vertices(), vertices);
    EXPECT_TRUE(tr.is_valid());
    std::vector<Cell_handle> star;
    tr.incident_cells(v, std::back_inserter(star));
    EXPECT_EQ(star.size(), boundary.size());

    // The same triangulation as one built from scratch over the same weighted points.
    std::vector<Weighted_point> now;
    for (auto it = tr.finite_vertices_begin(); it != tr.finite_vertices_end(); ++it) {
      now.push_back(it->point());
    }
    const Triangulation fresh(now.begin(), now.end());
    EXPECT_EQ(fresh.number_of_vertices(), tr.number_of_vertices());
    EXPECT_EQ(fresh.number_of_finite_cells(), tr.number_of_finite_cells());
    EXPECT_EQ(fresh.number_of_finite_facets(), tr.number_of_finite_facets());
  }
}

}  // namespace
}  // namespace rdmesh::detail
