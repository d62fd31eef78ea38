// Refinement in two lanes (core/src/refinement_lanes.h): the mesh is the same,
// bit for bit, with 1, 2 and 3 threads, most cell centres go in through the
// lanes, and the refined mesh keeps the rules the sequential refinement keeps.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <vector>

#include "rdmesh/mesher.h"
#include "test_domains.h"

namespace rdmesh {
namespace {

bool same_bits(const std::vector<Point3>& a, const std::vector<Point3>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Point3)) == 0);
}

MeshResult refine_with(int threads, double size) {
  MeshOptions options;
  options.threads = threads;
  options.exudation.enabled = false;  // refinement alone
  options.improvement.enabled = false;
  return generate_mesh(test::unit_sphere(), test::uniform_criteria(size), options);
}

double signed_volume(const TetMesh& m, const std::array<int, 4>& t) {
  const Point3 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]],
               d = m.vertices[t[3]];
  return dot(cross(b - a, c - a), d - a) / 6.0;
}

TEST(RefinementLanes, TheMeshIsTheSameOnAnyNumberOfThreads) {
  const MeshResult one = refine_with(1, 0.085);
  const RefinementStats& s = one.stats;
  // The lanes did a good part of R5 (at this small size the coarse start,
  // kept sequential, is half of it), and not all of it: both paths ran.
  ASSERT_GT(s.lane_rounds, 0u);
  // Some round needed its pools topped up: the lanes stopped and went on.
  EXPECT_GT(s.lane_steps, s.lane_rounds);
  EXPECT_GT(s.cell_centers_in_lanes, s.inserted_cell_centers / 3);
  EXPECT_LT(s.cell_centers_in_lanes, s.inserted_cell_centers);
  // Facets too (R3, R4), once the surface's balls are small: not the coarse start.
  EXPECT_GT(s.facet_centers_in_lanes, s.inserted_facet_centers / 10);
  EXPECT_LT(s.facet_centers_in_lanes, s.inserted_facet_centers);
  for (const int threads : {2, 3}) {
    SCOPED_TRACE(testing::Message() << threads << " threads");
    const MeshResult other = refine_with(threads, 0.085);
    EXPECT_TRUE(same_bits(one.mesh.vertices, other.mesh.vertices)) << "vertex coordinates differ";
    EXPECT_EQ(one.mesh.tets, other.mesh.tets);
    EXPECT_EQ(one.mesh.triangles, other.mesh.triangles);
    EXPECT_EQ(s.cell_centers_in_lanes, other.stats.cell_centers_in_lanes);
    EXPECT_EQ(s.facet_centers_in_lanes, other.stats.facet_centers_in_lanes);
    EXPECT_EQ(s.lane_rounds, other.stats.lane_rounds);
    EXPECT_EQ(s.lane_steps, other.stats.lane_steps);
    EXPECT_EQ(s.inserted_facet_centers, other.stats.inserted_facet_centers);
  }
}

/// The unit sphere refined to a cell size growing from 0.06 at x = -1 to 0.12
/// at x = 1, on `threads` threads; `thread_safe`: the field says it may be
/// called from several threads at once.
MeshResult refine_graded(int threads, bool thread_safe) {
  Criteria criteria = test::uniform_criteria(0.12);
  criteria.cell_size =
      ScalarField{0.0, [](const Point3& p) { return 0.09 + 0.03 * p.x; }, thread_safe};
  MeshOptions options;
  options.threads = threads;
  options.exudation.enabled = false;
  options.improvement.enabled = false;
  return generate_mesh(test::unit_sphere(), criteria, options);
}

TEST(RefinementLanes, TheSequentialStepsLeaveSmallElementsToTheLanes) {
  // The sequential steps park the small elements no lane owned when they were
  // queued (CellLevel::pop, FacetLevel::pop) instead of refining them: the
  // layers along the cuts and the surface go through the lanes. Refined on
  // the spot, 24% of the cell centres and 77% of the facet centres of this
  // sphere went in sequentially. The rounds' cuts take the three axes in turn
  // and an entry may cross two of them before the sequential steps take it:
  // with two axes and one crossing, 11.5% of the cell centres went in
  // sequentially, now 7.7%.
  const RefinementStats s = refine_with(1, 0.05).stats;
  ASSERT_GT(s.inserted_cell_centers, 10000u);
  EXPECT_GT(s.cell_centers_in_lanes, s.inserted_cell_centers * 90 / 100);
  EXPECT_GT(s.facet_centers_in_lanes, s.inserted_facet_centers * 60 / 100);
}

TEST(RefinementLanes, AThreadSafeCellSizeFieldRunsOnTwoThreadsWithTheSameMesh) {
  const MeshResult one = refine_graded(1, true);
  ASSERT_GT(one.stats.cell_centers_in_lanes, one.stats.inserted_cell_centers / 3);
  EXPECT_EQ(one.stats.lane_threads, 1);
  const MeshResult two = refine_graded(2, true);
  EXPECT_EQ(two.stats.lane_threads, 2);
  // A field that does not say so keeps the lanes on one thread, whatever the
  // threads asked for: it may be a callable that is not thread-safe.
  const MeshResult guarded = refine_graded(2, false);
  EXPECT_EQ(guarded.stats.lane_threads, 1);
  for (const MeshResult* other : {&two, &guarded}) {
    EXPECT_TRUE(same_bits(one.mesh.vertices, other->mesh.vertices)) << "vertex coordinates differ";
    EXPECT_EQ(one.mesh.tets, other->mesh.tets);
    EXPECT_EQ(one.mesh.triangles, other->mesh.triangles);
    EXPECT_EQ(one.stats.cell_centers_in_lanes, other->stats.cell_centers_in_lanes);
  }
}

TEST(RefinementLanes, AFacetFieldThatIsNotThreadSafeKeepsTheFacetsSequentialNotTheCells) {
  // A facet size that does not say it is thread-safe keeps the facets in the
  // sequential steps; the cells still run on two threads (they did not).
  const ImplicitOracle oracle = test::unit_sphere();
  Criteria criteria = test::uniform_criteria(0.085);
  criteria.facet_size = ScalarField{0.0, [](const Point3&) { return 0.085; }, false};
  MeshOptions options;
  options.threads = 2;
  options.exudation.enabled = false;
  options.improvement.enabled = false;
  const MeshResult two = generate_mesh(oracle, criteria, options);
  ASSERT_GT(two.stats.cell_centers_in_lanes, 0u);
  EXPECT_EQ(two.stats.facet_centers_in_lanes, 0u);
  EXPECT_EQ(two.stats.lane_threads, 2);
  options.threads = 1;
  const MeshResult one = generate_mesh(oracle, criteria, options);
  EXPECT_EQ(one.stats.lane_threads, 1);
  EXPECT_TRUE(same_bits(one.mesh.vertices, two.mesh.vertices)) << "vertex coordinates differ";
  EXPECT_EQ(one.mesh.tets, two.mesh.tets);
}

TEST(RefinementLanes, FieldsComposedOfThreadSafeFieldsAreThreadSafe) {
  const ScalarField safe{0.0, [](const Point3& p) { return 1 + p.x * p.x; }, true};
  const ScalarField unknown{0.0, [](const Point3& p) { return 1 + p.y * p.y; }};
  const ScalarField constant = ScalarField::uniform(0.5);
  EXPECT_TRUE(constant.is_concurrent());
  EXPECT_TRUE(safe.is_concurrent());
  EXPECT_FALSE(unknown.is_concurrent());
  const auto min_of = [](const ScalarField& a, const ScalarField& b) {
    return ScalarField::composed([a, b](const Point3& p) { return std::min(a(p), b(p)); },
                                 {&a, &b});
  };
  const ScalarField both_safe = min_of(safe, constant), mixed = min_of(safe, unknown);
  EXPECT_TRUE(both_safe.is_concurrent());
  EXPECT_FALSE(mixed.is_concurrent());
  EXPECT_DOUBLE_EQ(both_safe(Point3{0.5, 0, 0}), 0.5);
  EXPECT_DOUBLE_EQ(mixed(Point3{0.5, 2, 0}), 1.25);
}

TEST(RefinementLanes, TheLanesMeshIsAValidSphere) {
  const MeshResult r = refine_with(2, 0.085);
  const TetMesh& m = r.mesh;
  ASSERT_GT(m.tets.size(), 10000u);
  // Positively oriented tets filling the ball's volume (inscribed: a bit less).
  double volume = 0;
  for (const auto& t : m.tets) {
    const double v = signed_volume(m, t);
    ASSERT_GT(v, 0.0);
    volume += v;
  }
  const double ball = 4.0 / 3.0 * M_PI;
  EXPECT_NEAR(volume, ball, 0.02 * ball);
  // A closed boundary of sphere topology: every edge in two triangles, V - E + F = 2.
  std::map<std::pair<int, int>, int> edges;
  std::set<int> boundary_vertices;
  for (const auto& t : m.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++edges[{std::min(a, b), std::max(a, b)}];
      boundary_vertices.insert(a);
      ASSERT_NEAR(norm(m.vertices[a]), 1.0, 1e-6);  // on the exact surface
    }
  }
  for (const auto& [edge, count] : edges) ASSERT_EQ(count, 2);
  EXPECT_EQ(static_cast<long>(boundary_vertices.size()) - static_cast<long>(edges.size()) +
                static_cast<long>(m.triangles.size()),
            2);
  // R4 on every boundary triangle, the lanes' ones too: its circumradius within
  // the facet size (its surface ball is at least as large), its smallest angle
  // at least 25 degrees, and its circumcentre within the facet distance of the
  // sphere (the dual Voronoi edge of a triangle on the unit sphere goes
  // through the origin, so that distance is 1 - |circumcentre|).
  ASSERT_GT(r.stats.facet_centers_in_lanes, 0u);
  for (const auto& t : m.triangles) {
    const Point3 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
    const Point3 ab = b - a, ac = c - a, n = cross(ab, ac);
    const Point3 center = a + (1.0 / (2.0 * squared_norm(n))) * (squared_norm(ab) * cross(ac, n) +
                                                                 squared_norm(ac) * cross(n, ab));
    const double radius = norm(center - a);
    EXPECT_LE(radius, 0.085 * (1 + 1e-9));
    const double shortest =
        std::sqrt(std::min({squared_norm(ab), squared_norm(ac), squared_norm(c - b)}));
    // The smallest angle is opposite the shortest edge: sin = shortest / (2 R).
    EXPECT_GE(shortest / (2 * radius), std::sin(25 * M_PI / 180) * (1 - 1e-9));
    EXPECT_LE(1 - norm(center), 0.0085 * (1 + 1e-9));
  }
  // R5: every tet's circumradius within the cell size (the criterion refined to).
  for (const auto& t : m.tets) {
    const Point3 a = m.vertices[t[0]];
    const Point3 b = m.vertices[t[1]] - a, c = m.vertices[t[2]] - a, d = m.vertices[t[3]] - a;
    const Point3 num = squared_norm(b) * cross(c, d) + squared_norm(c) * cross(d, b) +
                       squared_norm(d) * cross(b, c);
    const double radius = norm(num) / (2.0 * dot(b, cross(c, d)));
    ASSERT_LE(radius, 0.085 * (1 + 1e-9));
  }
}

}  // namespace
}  // namespace rdmesh
