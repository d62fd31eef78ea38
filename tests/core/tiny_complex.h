// A restricted complex small enough to check by hand, for the tests of the
// refinement levels: the unit sphere's oracle and seven points, the origin and
// the octahedron (+-1, 0, 0), (0, +-1, 0), (0, 0, +-1) on the sphere. D(P) is
// the eight tetrahedra joining the origin to the octahedron's faces: their
// circumcenters (+-1/2, +-1/2, +-1/2) lie inside the sphere, so all eight are
// in D|O with squared radius 3/4 and shortest edge 1. The eight hull facets
// are in D|S: the dual ray of the facet with normal (1, 1, 1) / sqrt(3)
// crosses the sphere at that normal, the centre of its surface Delaunay ball.
#pragma once

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "level_cells.h"
#include "level_facets.h"
#include "restricted_complex.h"
#include "test_domains.h"

namespace rdmesh::test {

struct TinyComplex {
  /// `on_patch`: the octahedron's vertices are marked as points of the
  /// sphere's patch (as refine-facet would insert them); else they are
  /// volume points, and every facet of D|S violates R3.
  explicit TinyComplex(bool on_patch) {
    detail::Triangulation& tr = complex.triangulation();
    tr.insert(detail::to_weighted({0, 0, 0}));
    const PatchId patch = oracle.patches().at(0).id;
    for (int axis = 0; axis < 3; ++axis) {
      for (const double s : {-1.0, 1.0}) {
        Point3 p{0, 0, 0};
        (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = s;
        const detail::Vertex_handle v = tr.insert(detail::to_weighted(p));
        if (on_patch) {
          v->info().feature = detail::FeatureRef(patch);
        }
      }
    }
    complex.init_unstamped_cells();
    for (auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) {
      for (int i = 0; i < 4; ++i) {
        if (c->neighbor(i)->info().stamp > c->info().stamp) complex.update_facet(c, i);
      }
    }
  }

  /// Each facet of D|S once, from its finite cell.
  std::vector<std::pair<detail::Cell_handle, int>> restricted_facets() {
    std::vector<std::pair<detail::Cell_handle, int>> out;
    detail::Triangulation& tr = complex.triangulation();
    for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
      for (int i = 0; i < 4; ++i) {
        if (c->info().facet_patch[i] != detail::kNotRestricted) out.emplace_back(c, i);
      }
    }
    return out;
  }

  /// What `level` reports for each facet of D|S, and for each finite cell.
  std::vector<detail::Violation> violations(const detail::FacetLevel& level) {
    std::vector<detail::Violation> out;
    for (const auto& [c, i] : restricted_facets()) out.push_back(level.violation(c, i));
    return out;
  }
  std::vector<detail::Violation> violations(const detail::CellLevel& level) {
    std::vector<detail::Violation> out;
    const detail::Triangulation& tr = complex.triangulation();
    for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
      out.push_back(level.violation(c));
    }
    return out;
  }

  ImplicitOracle oracle = unit_sphere();
  detail::RestrictedComplex complex{oracle, /*surface_only=*/false};
};

/// Criteria no element of TinyComplex violates: sizes and distance 10,
/// facet angle 20 degrees, radius-edge ratio 2.
inline Criteria lenient_criteria() {
  Criteria c = uniform_criteria(10);
  c.facet_distance = ScalarField::uniform(10);
  c.facet_angle_deg = 20;
  return c;
}

/// Every report names `rule`, with `priority` (within `tolerance`).
inline void expect_all(const std::vector<detail::Violation>& reports, detail::Rule rule,
                       double priority, double tolerance) {
  ASSERT_FALSE(reports.empty());
  for (const detail::Violation& v : reports) {
    EXPECT_EQ(v.rule, rule);
    EXPECT_NEAR(v.priority, priority, tolerance);
  }
}

}  // namespace rdmesh::test
