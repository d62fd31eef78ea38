// The final local improvement (rdmesh/tet_improvement.h) on meshes built here:
// planted slivers it must remove by flips or by moving a free vertex, a
// sliver it must leave because removing it would flip an interface, and a
// shaken grid of two subdomains. After the pass, always: every tetrahedron
// positively oriented, the triangles, feature edges and corners identical,
// each subdomain's volume the same, the smallest dihedral angle not lower,
// and the same result twice.
#include "rdmesh/tet_improvement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

#include "mesh_checks.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_measures.h"

namespace rdmesh {
namespace {

using Face = std::array<int, 3>;

/// Adds tetrahedron (a, b, c, d) positively oriented.
void add_tet(TetMesh& mesh, std::array<int, 4> t, int label) {
  const auto& v = mesh.vertices;
  if (signed_volume(v[t[0]], v[t[1]], v[t[2]], v[t[3]]) < 0) std::swap(t[2], t[3]);
  mesh.tets.push_back(t);
  mesh.tet_subdomain.push_back(SubdomainId{label});
}

/// The faces of one tetrahedron only, or between two labels, as the triangles
/// (patch 1 outside, 2 between labels).
void add_boundary_triangles(TetMesh& mesh) {
  std::map<Face, std::vector<int>> faces;
  for (int t = 0; t < static_cast<int>(mesh.tets.size()); ++t) {
    const auto& q = mesh.tets[t];
    for (int i = 0; i < 4; ++i) {
      Face f{q[(i + 1) % 4], q[(i + 2) % 4], q[(i + 3) % 4]};
      std::sort(f.begin(), f.end());
      faces[f].push_back(t);
    }
  }
  for (const auto& [f, tets] : faces) {
    if (tets.size() == 1) {
      mesh.triangles.push_back(f);
      mesh.triangle_patch.push_back(PatchId{1});
    } else if (mesh.tet_subdomain[tets[0]] != mesh.tet_subdomain[tets[1]]) {
      mesh.triangles.push_back(f);
      mesh.triangle_patch.push_back(PatchId{2});
    }
  }
}

/// Everything the pass promises between `before` and `after`.
void expect_same_boundary_and_regions(const TetMesh& before, const TetMesh& after,
                                      const TetImprovementStats& s) {
  test::expect_positive_orientation(after);
  test::expect_conforming(after);
  EXPECT_EQ(after.vertices.size(), before.vertices.size() + s.vertex_insertions);
  EXPECT_EQ(after.triangles, before.triangles);
  EXPECT_EQ(after.triangle_patch, before.triangle_patch);
  EXPECT_EQ(after.edges, before.edges);
  EXPECT_EQ(after.edge_curve, before.edge_curve);
  EXPECT_EQ(after.corner_vertices, before.corner_vertices);
  // Vertices on a triangle or a feature edge did not move.
  std::set<int> fixed;
  for (const auto& t : before.triangles) fixed.insert(t.begin(), t.end());
  for (const auto& e : before.edges) fixed.insert(e.begin(), e.end());
  for (const int v : fixed) EXPECT_EQ(after.vertices[v], before.vertices[v]) << "vertex " << v;
  std::set<int> labels;
  for (const SubdomainId s : before.tet_subdomain) labels.insert(s.value);
  for (const int l : labels) {
    const double v0 = test::volume(before, SubdomainId{l}),
                 v1 = test::volume(after, SubdomainId{l});
    EXPECT_NEAR(v1, v0, 1e-12 * v0) << "subdomain " << l;
  }
  EXPECT_TRUE(s.ran);
  EXPECT_GE(s.min_dihedral_after_deg, s.min_dihedral_before_deg);
  EXPECT_NEAR(s.min_dihedral_before_deg, test::min_dihedral_deg(before), 1e-9);
  EXPECT_NEAR(s.min_dihedral_after_deg, test::min_dihedral_deg(after), 1e-9);
  EXPECT_EQ(s.tets_before, before.tets.size());
  EXPECT_EQ(s.tets_after, after.tets.size());
  std::size_t counted = 0;
  for (const std::size_t n : s.histogram_after) counted += n;
  EXPECT_EQ(counted, after.tets.size());
}

/// A square p0..p3 warped by +-eps (p0, p2 up) between apexes above and below:
/// five tetrahedra, one of them the flat p0p1p2p3, every vertex on the boundary.
/// Labels: the sliver `sliver`, the two above it `top`, the two below 1.
TetMesh warped_octahedron(double eps, int sliver = 1, int top = 1) {
  TetMesh mesh;
  mesh.vertices = {{0, 0, eps},  {1, 0, -eps},    {1, 1, eps},
                   {0, 1, -eps}, {0.5, 0.5, 0.8}, {0.5, 0.5, -0.8}};
  add_tet(mesh, {0, 1, 2, 3}, sliver);
  add_tet(mesh, {4, 0, 1, 2}, top);
  add_tet(mesh, {4, 0, 2, 3}, top);
  add_tet(mesh, {5, 1, 3, 0}, 1);
  add_tet(mesh, {5, 1, 3, 2}, 1);
  add_boundary_triangles(mesh);
  return mesh;
}

TEST(TetImprovement, FlipsAPlantedSliverBetweenBoundaryVertices) {
  const TetMesh before = warped_octahedron(0.02);
  ASSERT_LT(test::min_dihedral_deg(before), 5.0);
  TetMesh after = before;
  const TetImprovementStats s = improve_tets(after);
  expect_same_boundary_and_regions(before, after, s);
  EXPECT_GE(s.edge_removals, 1u);
  EXPECT_EQ(s.vertex_moves, 0u);  // every vertex is on the boundary
  EXPECT_GT(s.min_dihedral_after_deg, 30.0);
  EXPECT_EQ(after.tets.size(), 4u);  // the sliver's edge p0p2 or p1p3 is gone
}

TEST(TetImprovement, FlipsBelowAnInterfaceWithoutTouchingIt) {
  // The top tets are another subdomain: the sliver's upper faces are
  // interface triangles and stay; the sliver goes with the edge p1p3 below.
  const TetMesh before = warped_octahedron(0.02, 1, 2);
  TetMesh after = before;
  const TetImprovementStats s = improve_tets(after);
  expect_same_boundary_and_regions(before, after, s);
  EXPECT_EQ(s.edge_removals, 1u);
  EXPECT_GT(s.min_dihedral_after_deg, 10.0);
  ASSERT_EQ(after.tets.size(), 4u);
  EXPECT_EQ(after.tets[0], before.tets[1]);  // the top ones, untouched
  EXPECT_EQ(after.tets[1], before.tets[2]);
}

TEST(TetImprovement, NeverFlipsAnInterfaceEvenForASliver) {
  // The sliver is a subdomain of its own: every face of it is an interface.
  const TetMesh before = warped_octahedron(0.02, 2, 1);
  TetMesh after = before;
  const TetImprovementStats s = improve_tets(after);
  expect_same_boundary_and_regions(before, after, s);
  EXPECT_EQ(s.edge_removals + s.face_flips + s.vertex_moves + s.vertex_insertions, 0u);
  EXPECT_EQ(after.tets, before.tets);
  EXPECT_EQ(s.min_dihedral_after_deg, s.min_dihedral_before_deg);
}

TEST(TetImprovement, TwoThreeFlipOfAFlatBipyramid) {
  // Two tetrahedra on a wide triangle (smallest angle 11.3 degrees): three
  // around the apexes' edge are better (22.6).
  TetMesh before;
  before.vertices = {{0, 0, 0.5}, {0, 0, -0.5}};
  for (int k = 0; k < 3; ++k) {
    before.vertices.push_back({5 * std::cos(2 * M_PI * k / 3), 5 * std::sin(2 * M_PI * k / 3), 0});
  }
  add_tet(before, {0, 2, 3, 4}, 1);
  add_tet(before, {1, 2, 3, 4}, 1);
  add_boundary_triangles(before);
  TetMesh after = before;
  const TetImprovementStats s = improve_tets(after);
  expect_same_boundary_and_regions(before, after, s);
  EXPECT_EQ(s.face_flips, 1u);
  EXPECT_EQ(after.tets.size(), 3u);
  EXPECT_GT(s.min_dihedral_after_deg, s.min_dihedral_before_deg + 5);
}

/// An n^3 grid of unit cubes, six Kuhn tetrahedra each; label 1 for x < n/2,
/// 2 beyond when `two`; boundary and interface triangles.
TetMesh kuhn_grid(int n, bool two) {
  TetMesh mesh;
  const auto id = [n](int i, int j, int k) { return (i * (n + 1) + j) * (n + 1) + k; };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) mesh.vertices.push_back({double(i), double(j), double(k)});
  const std::array<std::array<int, 3>, 6> orders{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (const auto& o : orders) {
          std::array<int, 3> c{i, j, k};
          std::array<int, 4> t;
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[o[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          add_tet(mesh, t, two && 2 * i >= n ? 2 : 1);
        }
  add_boundary_triangles(mesh);
  return mesh;
}

TEST(TetImprovement, MovesAFreeVertexOffAPlantedSliver) {
  const TetMesh grid = kuhn_grid(4, false);
  TetMesh before = grid;
  // Vertex (2, 2, 2), interior: to within 0.03 of the plane of the face
  // opposite it in one of its tetrahedra.
  const int v = (2 * 5 + 2) * 5 + 2;
  const auto& tet = *std::find_if(before.tets.begin(), before.tets.end(), [&](const auto& t) {
    return std::find(t.begin(), t.end(), v) != t.end();
  });
  std::array<Point3, 3> face;
  int f = 0;
  for (const int w : tet) {
    if (w != v) face[f++] = before.vertices[w];
  }
  Point3 normal = cross(face[1] - face[0], face[2] - face[0]);
  normal = (1.0 / norm(normal)) * normal;
  const Point3 p = before.vertices[v];
  const double h = dot(p - face[0], normal);
  before.vertices[v] = p - (h - std::copysign(0.03, h)) * normal;
  test::expect_positive_orientation(before);
  ASSERT_LT(test::min_dihedral_deg(before), 6.0);
  TetMesh after = before;
  const TetImprovementStats s = improve_tets(after);
  expect_same_boundary_and_regions(before, after, s);
  EXPECT_GE(s.vertex_moves + s.edge_removals + s.face_flips, 1u);
  // Above the bound below which tetrahedra are treated.
  EXPECT_GE(s.min_dihedral_after_deg, TetImprovementOptions{}.bound_deg);
}

TEST(TetImprovement, ShakenGridOfTwoSubdomainsKeepsBoundaryInterfaceAndVolumes) {
  TetMesh before = kuhn_grid(6, true);
  // Shake every vertex off the triangles by up to 0.3 (a fixed sequence).
  std::set<int> fixed;
  for (const auto& t : before.triangles) fixed.insert(t.begin(), t.end());
  unsigned state = 12345;
  const auto next = [&state] {
    state = state * 1103515245u + 12345u;
    return ((state >> 8) & 0xffff) / 65535.0 - 0.5;
  };
  for (int v = 0; v < static_cast<int>(before.vertices.size()); ++v) {
    if (fixed.count(v)) continue;
    before.vertices[v] = before.vertices[v] + Point3{0.6 * next(), 0.6 * next(), 0.6 * next()};
  }
  test::expect_positive_orientation(before);
  const double start = test::min_dihedral_deg(before);
  TetMesh after = before;
  const TetImprovementStats s = improve_tets(after);
  expect_same_boundary_and_regions(before, after, s);
  EXPECT_GT(s.vertex_moves, 0u);
  EXPECT_GT(s.edge_removals + s.face_flips, 0u);
  EXPECT_GT(s.min_dihedral_after_deg, start + 5);
  std::printf(
      "shaken grid: %zu -> %zu tets, min dihedral %.2f -> %.2f deg, %zu edge removals, "
      "%zu face flips, %zu vertex moves, %d sweeps\n",
      s.tets_before, s.tets_after, s.min_dihedral_before_deg, s.min_dihedral_after_deg,
      s.edge_removals, s.face_flips, s.vertex_moves, s.sweeps);

  TetMesh again = before;
  (void)improve_tets(again);
  EXPECT_EQ(again.tets, after.tets);
  EXPECT_EQ(again.tet_subdomain, after.tet_subdomain);
  EXPECT_EQ(again.vertices, after.vertices);
}

TEST(TetImprovement, RefusesSecondOrderMeshesAndInvalidOptions) {
  TetMesh mesh = warped_octahedron(0.02);
  TetMesh second = mesh;
  second.tet_mid_nodes.resize(mesh.tets.size());
  EXPECT_THROW(improve_tets(second), InputError);
  for (const double bound : {0.0, -1.0, 71.0}) {
    TetImprovementOptions o;
    o.bound_deg = bound;
    EXPECT_THROW(improve_tets(mesh, o), InputError) << bound;
  }
  TetImprovementOptions o;
  o.time_limit_seconds = -1;
  EXPECT_THROW(improve_tets(mesh, o), InputError);
  o = {};
  o.max_sweeps = 0;  // nothing to do: the mesh stays as it is
  const TetMesh before = mesh;
  const TetImprovementStats s = improve_tets(mesh, o);
  EXPECT_EQ(mesh.tets, before.tets);
  EXPECT_EQ(s.min_dihedral_after_deg, s.min_dihedral_before_deg);
}

}  // namespace
}  // namespace rdmesh
