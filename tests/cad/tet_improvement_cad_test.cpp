// The final local improvement on shared STEP parts meshed with the default
// criteria: the restricted Delaunay mesh (improvement off) against the same
// mesh improved. Nothing of the boundary moves (triangles, patches, feature
// edges, corners, the vertices on them), each solid's volume is the same, every
// tetrahedron is positively oriented, the smallest dihedral angle never drops,
// fewer tetrahedra are below min(10 degrees, the part's smallest angle between
// faces at a feature), every one still below has its four vertices on the
// boundary, which this improver does not move, and the result is the same twice.
// (Such a tetrahedron is left to flips and insertions alone; the product's run
// also slides boundary vertices along the surface: see BoundaryMoves tests.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <set>

#include "core/mesh_checks.h"
#include "rdmesh/cad_oracle.h"
#include "rdmesh/mesh_measures.h"
#include "rdmesh/mesher.h"
#include "rdmesh/tet_improvement.h"
#include "shared_data.h"

namespace rdmesh {
namespace {

struct Part {
  const char* file;
  double target_deg;  ///< min(10, the smallest dihedral between faces, MANIFEST.md)
};

class TetImprovementCad : public ::testing::TestWithParam<Part> {};

TEST_P(TetImprovementCad, KeepsTheBoundaryAndVolumesAndReachesTheTarget) {
  const Part& part = GetParam();
  RDMESH_REQUIRE_SHARED_DATA(path, std::string("step/") + part.file);
  const auto oracle = load_cad_file(path);
  MeshOptions options;
  options.improvement.enabled = false;
  const MeshResult r = generate_mesh(*oracle, default_criteria(oracle->bounding_box()), options);
  const TetMesh& before = r.mesh;
  TetMesh after = before;
  const TetImprovementStats s = improve_tets(after);
  std::printf(
      "%s: %zu -> %zu tets, min dihedral %.2f -> %.2f deg, below 10 deg %zu -> %zu, %zu "
      "edge removals, %zu face flips, %zu vertex moves, %zu new vertices, %.3f s\n",
      part.file, s.tets_before, s.tets_after, s.min_dihedral_before_deg, s.min_dihedral_after_deg,
      s.histogram_before[0] + s.histogram_before[1], s.histogram_after[0] + s.histogram_after[1],
      s.edge_removals, s.face_flips, s.vertex_moves, s.vertex_insertions, s.seconds);

  test::expect_positive_orientation(after);
  test::expect_conforming(after);
  EXPECT_EQ(after.triangles, before.triangles);
  EXPECT_EQ(after.triangle_patch, before.triangle_patch);
  EXPECT_EQ(after.edges, before.edges);
  EXPECT_EQ(after.edge_curve, before.edge_curve);
  EXPECT_EQ(after.corner_vertices, before.corner_vertices);
  std::set<int> fixed;
  for (const auto& t : before.triangles) fixed.insert(t.begin(), t.end());
  std::size_t moved = 0;
  for (std::size_t v = 0; v < before.vertices.size(); ++v) {
    if (!(after.vertices[v] == before.vertices[v])) {
      ++moved;
      EXPECT_FALSE(fixed.count(static_cast<int>(v))) << "a boundary vertex moved: " << v;
    }
  }
  EXPECT_GT(moved, 0u);
  EXPECT_LE(moved, s.vertex_moves);
  for (const SubdomainInfo& sub : oracle->subdomains()) {
    const double v0 = test::volume(before, sub.id), v1 = test::volume(after, sub.id);
    EXPECT_NEAR(v1, v0, 1e-12 * v0) << sub.name;
  }
  EXPECT_NEAR(s.min_dihedral_before_deg, test::min_dihedral_deg(before), 1e-9);
  EXPECT_NEAR(s.min_dihedral_after_deg, test::min_dihedral_deg(after), 1e-9);
  EXPECT_GE(s.min_dihedral_after_deg, s.min_dihedral_before_deg);
  std::size_t below_before = 0, below_after = 0;
  for (const auto& t : before.tets) {
    const auto& v = before.vertices;
    if (dihedral_extremes_deg(v[t[0]], v[t[1]], v[t[2]], v[t[3]]).first < part.target_deg)
      ++below_before;
  }
  for (const auto& t : after.tets) {
    const auto& v = after.vertices;
    const double angle = dihedral_extremes_deg(v[t[0]], v[t[1]], v[t[2]], v[t[3]]).first;
    if (angle >= part.target_deg) continue;
    ++below_after;
    const bool locked = std::all_of(t.begin(), t.end(), [&](int i) { return fixed.count(i) > 0; });
    EXPECT_TRUE(locked) << "a tetrahedron with a free vertex stays at " << angle << " deg";
  }
  if (below_before > 0) {
    EXPECT_LT(below_after, below_before);
  }
  EXPECT_LE(s.tets_after, s.tets_before + s.tets_before / 5);
  EXPECT_EQ(after.vertices.size(), before.vertices.size() + s.vertex_insertions);

  TetMesh again = before;
  (void)improve_tets(again);
  EXPECT_EQ(again.tets, after.tets);
  EXPECT_EQ(again.tet_subdomain, after.tet_subdomain);
  EXPECT_EQ(again.vertices, after.vertices);
}

INSTANTIATE_TEST_SUITE_P(Shared, TetImprovementCad,
                         ::testing::Values(Part{"gmsh_Zylkopf.stp", 10},
                                           Part{"occt_screw.step", 10},
                                           Part{"occtsample_MBBGehauseRohteil.step", 10},
                                           Part{"gmsh_wrenchnut.stp", 10}),
                         [](const auto& info) { return test::file_test_name(info.param.file); });

}  // namespace
}  // namespace rdmesh
