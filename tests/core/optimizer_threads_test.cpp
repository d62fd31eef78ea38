// The optimizers after refinement (sliver exudation, then the local
// improvement of the tetrahedra) give the same mesh, bit for bit, with 1, 2
// and 3 threads (issue 19): their parallel loops are split and combined by
// fixed rules, never by scheduling.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "rdmesh/mesher.h"
#include "test_domains.h"

namespace rdmesh {
namespace {

/// Bitwise equality of two coordinate lists (== would let -0.0 pass for 0.0).
bool same_bits(const std::vector<Point3>& a, const std::vector<Point3>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Point3)) == 0);
}

MeshResult mesh_with(int threads) {
  MeshOptions options;
  options.threads = threads;
  // About 30 k tetrahedra: several chunks of the parallel loops (4096 items each).
  return generate_mesh(test::unit_sphere(), test::uniform_criteria(0.085), options);
}

TEST(OptimizerThreads, ExudationAndImprovementIndependentOfThreadCount) {
  const MeshResult one = mesh_with(1);
  // The case exercises what it claims: enough tets for several chunks, and
  // both optimizers changed the mesh.
  ASSERT_GT(one.mesh.tets.size(), 3 * 4096u);
  ASSERT_TRUE(one.exudation.ran);
  EXPECT_GT(one.exudation.moves_accepted, 0u);
  // Both ways of pumping ran: inside the two lanes, and where they meet.
  EXPECT_GT(one.exudation.moves_tried_in_lanes, 0u);
  EXPECT_LT(one.exudation.moves_tried_in_lanes, one.exudation.moves_tried);
  ASSERT_TRUE(one.improvement.ran);
  EXPECT_GT(one.improvement.edge_removals + one.improvement.face_flips +
                one.improvement.vertex_moves + one.improvement.boundary_moves,
            0u);
  for (const int threads : {2, 3}) {
    SCOPED_TRACE(testing::Message() << threads << " threads");
    const MeshResult other = mesh_with(threads);
    EXPECT_TRUE(same_bits(one.mesh.vertices, other.mesh.vertices)) << "vertex coordinates differ";
    EXPECT_EQ(one.mesh.tets, other.mesh.tets);
    ASSERT_EQ(one.mesh.tet_subdomain.size(), other.mesh.tet_subdomain.size());
    for (std::size_t t = 0; t < one.mesh.tet_subdomain.size(); ++t)
      ASSERT_EQ(one.mesh.tet_subdomain[t].value, other.mesh.tet_subdomain[t].value) << "tet " << t;
    EXPECT_EQ(one.mesh.triangles, other.mesh.triangles);
    EXPECT_EQ(one.exudation.moves_tried, other.exudation.moves_tried);
    EXPECT_EQ(one.exudation.moves_accepted, other.exudation.moves_accepted);
    EXPECT_EQ(one.exudation.moves_tried_in_lanes, other.exudation.moves_tried_in_lanes);
    EXPECT_EQ(one.exudation.histogram_after, other.exudation.histogram_after);
    EXPECT_EQ(one.exudation.min_dihedral_after_deg, other.exudation.min_dihedral_after_deg);
    EXPECT_EQ(one.improvement.edge_removals, other.improvement.edge_removals);
    EXPECT_EQ(one.improvement.face_flips, other.improvement.face_flips);
    EXPECT_EQ(one.improvement.vertex_moves, other.improvement.vertex_moves);
    EXPECT_EQ(one.improvement.vertex_insertions, other.improvement.vertex_insertions);
    EXPECT_EQ(one.improvement.histogram_after, other.improvement.histogram_after);
  }
}

}  // namespace
}  // namespace rdmesh
