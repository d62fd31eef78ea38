// Refiner::update_balls (core/src/ball_update.cpp): after the planner shrinks
// the balls the first check found in conflict, moving only the balls that
// changed must give the triangulation a fresh build of the new plan gives:
// the same weighted vertices on the same features, the same cells with the
// same labels, and the same restricted facets on the same patches (up to the
// choice between two adjacent patches that a fresh build makes too).
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>

#include "rdmesh/cad_oracle.h"
#include "refiner.h"

namespace rdmesh::detail {
namespace {

const std::filesystem::path kStep = std::filesystem::path(RDMESH_SOURCE_DIR) / "../shared/data/step";

using Key = std::tuple<double, double, double>;
Key key_of(const Vertex_handle& v) { return {v->point().x(), v->point().y(), v->point().z()}; }

// Everything about the initial triangulation that refinement reads, by geometry.
struct Signature {
  std::map<Key, std::tuple<double, int, int>> vertices;  // weight, dim, feature
  std::map<std::array<Key, 4>, int> cells;               // label
  std::map<std::array<Key, 3>, int> facets;              // patch of a restricted facet
  std::map<std::array<Key, 3>, std::pair<Point3, Point3>> duals;  // between finite cells
};

Signature signature(const Triangulation& tr) {
  Signature s;
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    s.vertices[key_of(v)] = {v->point().weight(), static_cast<int>(v->info().dim),
                             v->info().feature};
  }
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
    std::array<Key, 4> cell;
    for (int k = 0; k < 4; ++k) cell[k] = key_of(c->vertex(k));
    std::sort(cell.begin(), cell.end());
    s.cells[cell] = c->info().label;
    for (int i = 0; i < 4; ++i) {
      if (c->info().facet_patch[i] == 0) continue;
      std::array<Key, 3> facet;
      for (int k = 0; k < 3; ++k) facet[k] = key_of(c->vertex((i + 1 + k) & 3));
      std::sort(facet.begin(), facet.end());
      s.facets[facet] = c->info().facet_patch[i];
      if (!tr.is_infinite(c->neighbor(i))) {
        s.duals[facet] = {c->info().circumcenter, c->neighbor(i)->info().circumcenter};
      }
    }
  }
  return s;
}

class BallUpdate : public ::testing::TestWithParam<const char*> {};

TEST_P(BallUpdate, GivesTheTriangulationAFreshBuildGives) {
  const std::filesystem::path path = kStep / GetParam();
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
  const std::unique_ptr<CadOracle> oracle = load_cad_file(path.string());
  const Criteria criteria = default_criteria(oracle->bounding_box());
  std::vector<ProtectedCurve> curves;
  for (const CurveInfo& info : oracle->curves()) curves.push_back({info, &oracle->curve(info.id)});
  ProtectionPlanner planner(std::move(curves), oracle->corners(), criteria,
                            1e-4 * oracle->bounding_box().diagonal(), oracle.get());
  ProtectionPlan plan = planner.plan();
  const MeshOptions options;

  Refiner moved(*oracle, criteria, options, &plan);
  moved.insert_initial_points();
  moved.refine(true);
  // These parts have balls in conflict at the first check (a restart).
  ASSERT_FALSE(moved.conflicts().empty());
  ASSERT_TRUE(planner.shrink(moved.conflicts(), plan));
  ASSERT_TRUE(moved.update_balls());
  EXPECT_TRUE(moved.conflicts().empty());

  Refiner fresh(*oracle, criteria, options, &plan);
  fresh.insert_initial_points();

  const Signature a = signature(moved.triangulation()), b = signature(fresh.triangulation());
  EXPECT_EQ(a.vertices.size(), b.vertices.size());
  EXPECT_TRUE(a.vertices == b.vertices) << "the vertices differ";
  EXPECT_EQ(a.cells.size(), b.cells.size());
  EXPECT_TRUE(a.cells == b.cells) << "the cells or their labels differ";
  // The same restricted facets. A dual edge crossing two patches reports the
  // crossing met first from the side its cell was labeled from (a fresh build
  // does the same): there, and only there, the patch may differ.
  ASSERT_EQ(a.facets.size(), b.facets.size());
  std::size_t other_patch = 0;
  for (const auto& [facet, patch] : a.facets) {
    const auto it = b.facets.find(facet);
    ASSERT_TRUE(it != b.facets.end()) << "a restricted facet of the update only";
    if (it->second == patch) continue;
    ++other_patch;
    ASSERT_TRUE(a.duals.count(facet));
    const auto [p, q] = a.duals.at(facet);
    const auto from_p = oracle->intersect(p, q), from_q = oracle->intersect(q, p);
    ASSERT_TRUE(from_p && from_q);
    const std::set<int> ends{from_p->patch.value, from_q->patch.value};
    EXPECT_EQ(ends, (std::set<int>{patch, it->second})) << "patches " << patch << ", " << it->second;
  }
  EXPECT_LE(other_patch, a.facets.size() / 100);
  EXPECT_EQ(moved.stats().initial_points, fresh.stats().initial_points);
  EXPECT_GT(b.facets.size(), 100u);  // the comparison saw a restricted surface
}

INSTANTIATE_TEST_SUITE_P(CadParts, BallUpdate,
                         ::testing::Values("gmsh_Kurbelwelle.stp", "occtsample_ANC101.step"));

}  // namespace
}  // namespace rdmesh::detail
