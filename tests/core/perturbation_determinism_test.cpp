// Sliver perturbation (ExudationOptions::perturb) gives the same mesh, bit for
// bit and in the same order, on every call: its vertex moves must not depend
// on where the allocator put the cells and vertices. (CGAL's
// move_if_no_collision, which it once used, fills the removed vertex's hole
// in the address order of vertex handles, and the numbering of 3,884-5,018 of
// 5,470 vertices changed from one call to the next in the same process.)
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <vector>

#include "rdmesh/mesher.h"
#include "test_domains.h"

namespace rdmesh {
namespace {

MeshResult mesh_with_perturbation(const DomainOracle& oracle, const Criteria& criteria) {
  MeshOptions options;
  options.improvement.enabled = false;
  options.exudation.self_check = true;
  options.exudation.perturb = true;
  options.exudation.perturb_bound_deg = 25;  // more moves than the default
  return generate_mesh(oracle, criteria, options);
}

TEST(PerturbationDeterminism, EveryCallGivesTheSameMeshInTheSameOrder) {
  const ImplicitOracle oracle = test::nested_spheres();
  Criteria criteria = test::uniform_criteria(0.1);
  criteria.facet_distance = 0.003;
  const MeshResult first = mesh_with_perturbation(oracle, criteria);
  const ExudationStats& s = first.exudation;
  std::printf("perturbation: %zu/%zu moves, min dihedral %.2f -> %.2f -> %.2f deg\n",
              s.perturb_moves_accepted, s.perturb_moves_tried, s.min_dihedral_before_deg,
              s.min_dihedral_after_perturb_deg, s.min_dihedral_after_deg);
  ASSERT_GT(s.perturb_moves_accepted, 0u);
  EXPECT_GT(s.min_dihedral_after_perturb_deg, s.min_dihedral_before_deg);
  // Blocks of assorted sizes kept alive between the calls: the next call's
  // cells and vertices land elsewhere, in another address order.
  std::vector<std::unique_ptr<char[]>> ballast;
  for (int call = 0; call < 3; ++call) {
    for (int k = 0; k < 200; ++k)
      ballast.emplace_back(
          new char[static_cast<std::size_t>(64 + (k * 7919 + call * 104729) % 4096)]);
    const MeshResult again = mesh_with_perturbation(oracle, criteria);
    EXPECT_EQ(again.exudation.perturb_moves_accepted, first.exudation.perturb_moves_accepted);
    ASSERT_EQ(again.mesh.vertices.size(), first.mesh.vertices.size());
    ASSERT_EQ(again.mesh.tets.size(), first.mesh.tets.size());
    std::size_t moved_vertices = 0, other_tets = 0;
    for (std::size_t i = 0; i < first.mesh.vertices.size(); ++i) {
      const Point3 &a = first.mesh.vertices[i], &b = again.mesh.vertices[i];
      moved_vertices += !(a.x == b.x && a.y == b.y && a.z == b.z);
    }
    for (std::size_t t = 0; t < first.mesh.tets.size(); ++t)
      other_tets += first.mesh.tets[t] != again.mesh.tets[t] ||
                    first.mesh.tet_subdomain[t] != again.mesh.tet_subdomain[t];
    EXPECT_EQ(moved_vertices, 0u) << "call " << call + 2;
    EXPECT_EQ(other_tets, 0u) << "call " << call + 2;
  }
}

}  // namespace
}  // namespace rdmesh
