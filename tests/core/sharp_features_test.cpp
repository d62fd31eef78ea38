// Refinement with sharp curves (protecting balls, and RR-7912's rules R1, R2
// with the encroachment cascade), checked against the output properties of section 4: each curve's
// restricted edges form one chain of consecutive samples, each patch's facets
// form a surface of the right Euler characteristic, the boundary is closed.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "capped_cylinder_oracle.h"
#include "mesh_checks.h"
#include "rdmesh/mesh_measures.h"
#include "rdmesh/mesher.h"
#include "test_domains.h"

namespace rdmesh {
namespace {

/// Edges of `curve` form one closed cycle (every vertex of degree 2, connected).
void expect_closed_chain(const TetMesh& mesh, CurveId curve) {
  std::map<int, std::vector<int>> adjacent;
  std::size_t n = 0;
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    if (mesh.edge_curve[e] != curve) continue;
    adjacent[mesh.edges[e][0]].push_back(mesh.edges[e][1]);
    adjacent[mesh.edges[e][1]].push_back(mesh.edges[e][0]);
    ++n;
  }
  ASSERT_GE(n, 3u);
  for (const auto& [v, list] : adjacent) EXPECT_EQ(list.size(), 2u) << "vertex " << v;
  // Walk the cycle from any vertex: it must visit every edge.
  int prev = adjacent.begin()->first, cur = adjacent.begin()->second[0];
  std::size_t steps = 1;
  while (cur != adjacent.begin()->first && steps <= n) {
    const auto& next = adjacent[cur];
    const int nxt = next[0] == prev ? next[1] : next[0];
    prev = cur;
    cur = nxt;
    ++steps;
  }
  EXPECT_EQ(steps, n) << "the curve's edges are not one cycle";
}

/// Every feature edge is an edge of some tetrahedron.
void expect_edges_in_mesh(const TetMesh& mesh) {
  std::set<std::pair<int, int>> tet_edges;
  for (const auto& t : mesh.tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) tet_edges.insert(std::minmax(t[i], t[j]));
  for (const auto& e : mesh.edges) EXPECT_TRUE(tet_edges.count(std::minmax(e[0], e[1])));
}

class SharpFeatures : public testing::TestWithParam<FeatureMethod> {};

TEST_P(SharpFeatures, CappedCylinderHasThreePatchesAndTwoClosedChains) {
  const test::CappedCylinderOracle oracle(0.5, 0.5);
  const Criteria criteria = test::uniform_criteria(0.1);
  MeshOptions options;
  options.features = GetParam();
  const MeshResult result = generate_mesh(oracle, criteria, options);
  const TetMesh& mesh = result.mesh;
  test::expect_positive_orientation(mesh);
  test::expect_conforming(mesh);
  EXPECT_FALSE(result.stats.guard_fired());
  EXPECT_EQ(result.stats.unmeshed_feature_edges, 0u);
  EXPECT_EQ(euler_characteristic(mesh.triangles), 2);
  EXPECT_EQ(euler_characteristic(test::patch_triangles(mesh, PatchId{1})), 0);  // annulus
  EXPECT_EQ(euler_characteristic(test::patch_triangles(mesh, PatchId{2})), 1);  // disk
  EXPECT_EQ(euler_characteristic(test::patch_triangles(mesh, PatchId{3})), 1);  // disk
  expect_closed_chain(mesh, CurveId{1});
  expect_closed_chain(mesh, CurveId{2});
  expect_edges_in_mesh(mesh);
  // Curve vertices lie on their circle; edges stay within the facet distance of it.
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const Point3 a = mesh.vertices[mesh.edges[e][0]], b = mesh.vertices[mesh.edges[e][1]];
    const double z = mesh.edge_curve[e].value == 1 ? 0.5 : -0.5;
    EXPECT_NEAR(std::hypot(a.x, a.y), 0.5, 1e-9);
    EXPECT_NEAR(a.z, z, 1e-9);
    const Point3 m = 0.5 * (a + b);
    EXPECT_LE(0.5 - std::hypot(m.x, m.y), criteria.facet_distance.constant);
  }
  const double exact = M_PI * 0.25 * 1.0;
  EXPECT_NEAR(test::volume(mesh), exact, 0.01 * exact);
}

INSTANTIATE_TEST_SUITE_P(Methods, SharpFeatures,
                         testing::Values(FeatureMethod::kProtectingBalls,
                                         FeatureMethod::kRefineEdges),
                         [](const auto& info) {
                           return info.param == FeatureMethod::kProtectingBalls ? "protect"
                                                                                : "refine";
                         });

}  // namespace
}  // namespace rdmesh
