// The refiner's incremental bookkeeping of D|O and D|S (labels set once per
// new cell, restricted facets recomputed only around each insertion, surface
// centers stored out of line) equals a recomputation from scratch on the
// final triangulation, and the queues' stale-entry bookkeeping lets no bad
// element through.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "optimize/sliver_exuder.h"
#include "refiner.h"
#include "simplex_geometry.h"
#include "test_domains.h"

namespace rdmesh::detail {
namespace {

double distance_to_line(const Point3& x, const Point3& origin, const Point3& unit) {
  const Point3 d = x - origin;
  return norm(d - dot(d, unit) * unit);
}

/// The nested spheres refined at a uniform size (the refiner keeps references
/// to the oracle, the criteria and the options: they live here with it).
struct RefinedNestedSpheres {
  explicit RefinedNestedSpheres(double size)
      : oracle(test::nested_spheres()),
        criteria(criteria_for(oracle, size)),
        refiner(oracle, criteria, options, nullptr) {
    refiner.insert_initial_points();
    refiner.refine();
  }
  static Criteria criteria_for(const ImplicitOracle& oracle, double size) {
    Criteria c = test::uniform_criteria(size);
    c.min_size = c.min_size_for(oracle.bounding_box());
    return c;
  }
  const ImplicitOracle oracle;
  const Criteria criteria;
  const MeshOptions options;
  Refiner refiner;
};

TEST(RestrictedComplex, IncrementalBookkeepingEqualsARecomputation) {
  RefinedNestedSpheres run(0.12);
  const ImplicitOracle& oracle = run.oracle;
  const Triangulation& tr = run.refiner.triangulation();
  ASSERT_GT(tr.number_of_finite_cells(), 5000u);

  std::size_t restricted = 0, labeled = 0;
  std::map<int, std::size_t> per_patch;
  for (auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) {
    const CellInfo& info = c->info();
    ASSERT_NE(info.stamp, 0u) << "a live cell without a stamp";
    if (tr.is_infinite(c)) {
      EXPECT_EQ(info.label, 0);
    } else {
      // D|O: the label is the oracle's at the circumcenter, computed afresh.
      std::array<Point3, 4> p;
      for (int k = 0; k < 4; ++k) p[k] = to_point3(c->vertex(k)->point());
      const Point3 center = tet_circumcenter(p[0], p[1], p[2], p[3]);
      if (!is_finite(center)) {
        EXPECT_EQ(info.label, 0);
      } else {
        ASSERT_LE(norm(center - info.circumcenter), 1e-12 * (1 + norm(center)));
        EXPECT_EQ(info.label, oracle.locate(info.circumcenter).label.value);
      }
      labeled += info.label != 0;
    }
    for (int i = 0; i < 4; ++i) {
      const auto n = c->neighbor(i);
      const int j = n->index(c);
      // Both copies of a facet agree.
      ASSERT_EQ(info.facet_patch[i], n->info().facet_patch[j]);
      // D|S: restricted exactly when the dual edge joins two labels.
      EXPECT_EQ(info.facet_patch[i] != kNotRestricted, info.label != n->info().label);
      if (info.facet_patch[i] == kNotRestricted) continue;
      const Point3 sc = static_cast<const CellInfo&>(info).surface_center[i];
      ASSERT_EQ(sc, static_cast<const CellInfo&>(n->info()).surface_center[j]);
      if (n->info().stamp < info.stamp) continue;  // each facet once below
      ++restricted;
      ++per_patch[info.facet_patch[i].value];
      // The surface center is on the patch (sphere of radius 0.5 or 1, by patch)...
      const double r = norm(sc);
      EXPECT_TRUE(std::abs(r - 0.5) < 1e-6 || std::abs(r - 1.0) < 1e-6) << r;
      // ...and on the facet's dual Voronoi edge: on the line through the
      // facet's circumcenter along its normal, between the cells' centers.
      const Point3 q0 = to_point3(c->vertex((i + 1) & 3)->point());
      const Point3 q1 = to_point3(c->vertex((i + 2) & 3)->point());
      const Point3 q2 = to_point3(c->vertex((i + 3) & 3)->point());
      Point3 normal = cross(q1 - q0, q2 - q0);
      normal = (1 / norm(normal)) * normal;
      const Point3 origin = triangle_circumcenter(q0, q1, q2);
      EXPECT_LT(distance_to_line(sc, origin, normal), 1e-7);
      if (!tr.is_infinite(c) && !tr.is_infinite(n)) {
        const double a = dot(info.circumcenter - origin, normal);
        const double b = dot(n->info().circumcenter - origin, normal);
        const double s = dot(sc - origin, normal);
        EXPECT_LE(std::min(a, b) - 1e-9, s);
        EXPECT_LE(s, std::max(a, b) + 1e-9);
      }
    }
  }
  EXPECT_GT(labeled, 5000u);
  // Both spheres are sampled: two patches, each with many facets.
  ASSERT_EQ(per_patch.size(), 2u);
  for (const auto& [patch, count] : per_patch) EXPECT_GT(count, 200u) << "patch " << patch;
  EXPECT_GT(restricted, 400u);
}

/// Cells holding surface-center storage, and cells with a restricted facet.
std::pair<std::size_t, std::size_t> storage_counts(const Triangulation& tr) {
  std::size_t stored = 0, along_surface = 0;
  for (auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) {
    stored += c->info().surface_center.has_storage();
    const auto& patches = c->info().facet_patch;
    along_surface +=
        std::any_of(patches.begin(), patches.end(), [](PatchId p) { return p != kNotRestricted; });
  }
  return {stored, along_surface};
}

// The surface centers live out of line so that only cells along the surface
// pay for them. Exudation once gave storage to nearly every cell it rebuilt
// (a read through a non-const cell created it): 100 MB of 360 at 1.1 M tets.
TEST(RestrictedComplex, SurfaceCentersAreStoredOnlyAlongTheSurface) {
  RefinedNestedSpheres run(0.06);
  Triangulation& tr = run.refiner.triangulation();
  const auto [stored_before, surface_before] = storage_counts(tr);
  const std::size_t cells = tr.number_of_cells();
  ASSERT_GT(surface_before, 400u);
  EXPECT_LE(stored_before, 2 * surface_before);
  EXPECT_LT(stored_before, cells / 4);

  const ExudationStats stats = exude_slivers(tr, run.criteria, run.options.exudation);
  ASSERT_TRUE(stats.ran);
  ASSERT_GT(stats.moves_accepted, 100u);
  const auto [stored_after, surface_after] = storage_counts(tr);
  EXPECT_EQ(surface_after, surface_before) << "exudation keeps the restricted facets";
  EXPECT_LE(stored_after, 2 * surface_after);
  EXPECT_LT(stored_after, tr.number_of_cells() / 4);
}

}  // namespace
}  // namespace rdmesh::detail
