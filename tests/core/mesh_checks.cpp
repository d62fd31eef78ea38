#include "mesh_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <numeric>

#include "rdmesh/mesh_measures.h"

namespace rdmesh::test {
namespace {

using Face = std::array<int, 3>;

Face sorted(Face f) {
  std::sort(f.begin(), f.end());
  return f;
}

Point3 circumcenter(Point3 a, Point3 b, Point3 c, Point3 d) {
  // Solve 2 [b-a; c-a; d-a] x = [|b|^2-|a|^2, ...] relative to a, by Cramer's rule.
  const Point3 u = b - a, v = c - a, w = d - a;
  const double det = 2.0 * dot(u, cross(v, w));
  const Point3 num =
      squared_norm(u) * cross(v, w) + squared_norm(v) * cross(w, u) + squared_norm(w) * cross(u, v);
  return a + (1.0 / det) * num;
}

}  // namespace

void expect_positive_orientation(const TetMesh& mesh) {
  std::size_t bad = 0;
  for (const auto& t : mesh.tets) {
    const auto& v = mesh.vertices;
    if (!(signed_volume(v[t[0]], v[t[1]], v[t[2]], v[t[3]]) > 0)) ++bad;
  }
  EXPECT_EQ(bad, 0u) << "tetrahedra with non-positive orientation";
}

void expect_conforming(const TetMesh& mesh) {
  std::map<Face, std::vector<int>> faces;  // sorted face -> incident tets
  for (int t = 0; t < static_cast<int>(mesh.tets.size()); ++t) {
    const auto& q = mesh.tets[t];
    for (int i = 0; i < 4; ++i) {
      faces[sorted({q[(i + 1) % 4], q[(i + 2) % 4], q[(i + 3) % 4]})].push_back(t);
    }
  }
  std::set<Face> expected;  // faces between different labels
  for (const auto& [face, tets] : faces) {
    ASSERT_LE(tets.size(), 2u) << "a face shared by more than two tetrahedra";
    if (tets.size() == 1 || mesh.tet_subdomain[tets[0]] != mesh.tet_subdomain[tets[1]]) {
      expected.insert(face);
    }
  }
  std::set<Face> written;
  for (const auto& tri : mesh.triangles) {
    EXPECT_TRUE(written.insert(sorted(tri)).second) << "a triangle is written twice";
  }
  EXPECT_EQ(written, expected) << "labelled triangles differ from the label boundaries";
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& t : mesh.tets)
    for (int i : t) used[i] = true;
  EXPECT_EQ(std::count(used.begin(), used.end(), false), 0) << "unused vertices";
}

void expect_labels_match_oracle(const TetMesh& mesh, const DomainOracle& oracle) {
  std::size_t mismatches = 0;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& q = mesh.tets[t];
    const auto& v = mesh.vertices;
    const Point3 c = circumcenter(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);
    if (oracle.locate(c).label != mesh.tet_subdomain[t]) ++mismatches;
  }
  // Circumcenters within rounding of the boundary may flip; allow none in practice.
  EXPECT_EQ(mismatches, 0u) << "tets whose label differs from the oracle at the circumcenter";
}

std::vector<Face> patch_triangles(const TetMesh& mesh, PatchId patch) {
  std::vector<Face> out;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    if (patch.value == 0 || mesh.triangle_patch[i] == patch) out.push_back(mesh.triangles[i]);
  }
  return out;
}

int connected_components(const std::vector<Face>& triangles) {
  std::vector<int> parent(triangles.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> find = [&](int x) {
    return parent[x] == x ? x : parent[x] = find(parent[x]);
  };
  std::map<std::pair<int, int>, int> edge_owner;
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    for (int i = 0; i < 3; ++i) {
      int a = triangles[t][i], b = triangles[t][(i + 1) % 3];
      if (a > b) std::swap(a, b);
      auto [it, inserted] = edge_owner.emplace(std::make_pair(a, b), t);
      if (!inserted) parent[find(t)] = find(it->second);
    }
  }
  int count = 0;
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) count += find(t) == t;
  return count;
}

std::map<int, int> curve_degrees(const TetMesh& mesh, CurveId curve, std::size_t& count) {
  std::map<int, int> degree;
  count = 0;
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    if (mesh.edge_curve[e] != curve) continue;
    ++degree[mesh.edges[e][0]];
    ++degree[mesh.edges[e][1]];
    ++count;
  }
  return degree;
}

double volume(const TetMesh& mesh, SubdomainId sub) {
  double total = 0;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    if (sub.value != 0 && mesh.tet_subdomain[t] != sub) continue;
    const auto& q = mesh.tets[t];
    const auto& v = mesh.vertices;
    total += signed_volume(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);
  }
  return total;
}

double min_dihedral_deg(const TetMesh& mesh) {
  double worst = 180;
  for (const auto& t : mesh.tets) {
    const auto& v = mesh.vertices;
    for (double a : dihedral_angles_deg(v[t[0]], v[t[1]], v[t[2]], v[t[3]]))
      worst = std::min(worst, a);
  }
  return worst;
}

}  // namespace rdmesh::test
