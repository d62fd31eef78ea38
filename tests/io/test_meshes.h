// Small labelled meshes built by hand for the io tests.
#pragma once

#include <algorithm>
#include <array>
#include <map>
#include <vector>

#include "rdmesh/mesh_measures.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh::testing {

/// Box [0, 2s] x [0, s] x [0, s] made of two cubes, each split into the 6 Kuhn
/// tetrahedra around its main diagonal (conforming across x = s). The cube
/// x < s is subdomain 1 ("left"), the other subdomain 2 ("right").
/// Patches: 1 = outer boundary of the left cube (5 squares, 10 triangles),
/// 2 = outer boundary of the right cube (10 triangles), 3 = interface x = s
/// (2 triangles). Triangles are oriented as TetMesh requires: outward on the
/// outer boundary, towards subdomain 1 on the interface.
inline TetMesh two_cube_mesh(double s = 0.1) {
  TetMesh m;
  auto index = [](int i, int j, int k) { return i + 3 * j + 6 * k; };  // i in 0..2, j,k in 0..1
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) m.vertices.push_back({s * i, s * j, s * k});

  const std::array<std::array<int, 3>, 6> perms{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (int cube = 0; cube < 2; ++cube) {
    for (const auto& perm : perms) {
      std::array<int, 3> c{cube, 0, 0};
      std::array<int, 4> tet{};
      tet[0] = index(c[0], c[1], c[2]);
      for (int step = 0; step < 3; ++step) {
        ++c[perm[step]];
        tet[step + 1] = index(c[0], c[1], c[2]);
      }
      const auto& v = m.vertices;
      if (signed_volume(v[tet[0]], v[tet[1]], v[tet[2]], v[tet[3]]) < 0) std::swap(tet[2], tet[3]);
      m.tets.push_back(tet);
      m.tet_subdomain.push_back(SubdomainId(cube + 1));
    }
  }

  // Faces seen once are on the boundary; faces shared by different subdomains
  // are interfaces. Each face is kept oriented outward from the tet with the
  // larger subdomain id (so the interface normal points towards subdomain 1).
  struct Seen {
    std::array<int, 3> oriented;
    int subdomain;
    int count;
  };
  std::map<std::array<int, 3>, Seen> faces;
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    const auto& tet = m.tets[t];
    // Face opposite vertex i, ordered so that its normal points away from vertex i.
    const std::array<std::array<int, 3>, 4> local{{{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};
    for (const auto& f : local) {
      std::array<int, 3> face{tet[f[0]], tet[f[1]], tet[f[2]]};
      std::array<int, 3> key = face;
      std::sort(key.begin(), key.end());
      const int sub = m.tet_subdomain[t].value;
      auto [it, inserted] = faces.try_emplace(key, Seen{face, sub, 0});
      ++it->second.count;
      if (!inserted && sub > it->second.subdomain) it->second = {face, sub, it->second.count};
    }
  }
  for (const auto& [key, seen] : faces) {
    const bool interface = seen.count == 2 && m.vertices[key[0]].x == s &&
                           m.vertices[key[1]].x == s && m.vertices[key[2]].x == s;
    if (seen.count == 1 || interface) {
      m.triangles.push_back(seen.oriented);
      m.triangle_patch.push_back(PatchId(interface ? 3 : seen.subdomain));
    }
  }
  m.subdomains = {{SubdomainId(1), "left"}, {SubdomainId(2), "right"}};
  m.patches = {{PatchId(1), "left skin", kOutside, SubdomainId(1)},
               {PatchId(2), "right skin", kOutside, SubdomainId(2)},
               {PatchId(3), "interface", SubdomainId(1), SubdomainId(2)}};
  return m;
}

/// The triangles of `m` with patch `p`.
inline std::vector<std::array<int, 3>> triangles_of(const TetMesh& m, int p) {
  std::vector<std::array<int, 3>> out;
  for (std::size_t f = 0; f < m.triangles.size(); ++f) {
    if (m.triangle_patch[f].value == p) out.push_back(m.triangles[f]);
  }
  return out;
}

/// A torus surface: an n x m grid of quads with periodic wrap, two triangles each.
inline std::vector<std::array<int, 3>> torus_triangles(int n, int m) {
  std::vector<std::array<int, 3>> t;
  auto id = [&](int i, int j) { return (i % n) * m + (j % m); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return t;
}

/// The surface of the unit cube: 8 vertices (index x + 2y + 4z), 12 triangles.
inline std::vector<std::array<int, 3>> cube_surface_triangles() {
  return {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
          {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
}

}  // namespace rdmesh::testing
