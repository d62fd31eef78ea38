// Small labelled meshes built by hand for the io tests.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
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

/// two_cube_mesh(s) with sharp features: the 12 edges of the box as open
/// curves between its 8 corners, plus the rim of the interface square x = s as
/// a closed curve.
///   - corners 1..8: box corner (i, j, k), i, j, k in {0, 1} (scaled by 2s, s, s),
///     has id 1 + i + 2j + 4k;
///   - curves 1..4 "x<j><k>": along x from corner (0,j,k) to (1,j,k), two mesh
///     edges each (through the middle vertex), incident to patches 1 and 2;
///   - curves 5..8 "y<i><k>" and 9..12 "z<i><j>": one mesh edge each, incident to
///     patch 1 (i = 0) or 2 (i = 1);
///   - curve 13 "rim": closed, parameter [0, 4], the 4 edges of the interface
///     square, incident to patches 1, 2 and 3.
/// Every open curve has parameter range [0, 1]; edges follow the parameter.
inline TetMesh featured_two_cube_mesh(double s = 0.1) {
  TetMesh m = two_cube_mesh(s);
  auto vertex = [](int i, int j, int k) { return i + 3 * j + 6 * k; };                // i in 0..2
  auto corner = [](int i, int j, int k) { return CornerId(1 + i + 2 * j + 4 * k); };  // i in 0..1
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        m.corner_vertices.push_back(vertex(2 * i, j, k));
        m.corner_ids.push_back(corner(i, j, k));
        m.corners.push_back({corner(i, j, k), m.vertices[vertex(2 * i, j, k)], {}, {}});
      }
  auto add_curve = [&](const std::string& name, std::vector<int> chain, CornerId a, CornerId b,
                       std::vector<PatchId> patches) {
    const CurveId id(static_cast<int>(m.curves.size()) + 1);
    for (std::size_t e = 0; e + 1 < chain.size(); ++e) {
      m.edges.push_back({chain[e], chain[e + 1]});
      m.edge_curve.push_back(id);
    }
    const bool closed = a.value == 0;
    m.curves.push_back({id, name, closed, 0.0, closed ? 4.0 : 1.0, a, b, patches});
    for (CornerId c : {a, b}) {
      if (c.value == 0) continue;
      CornerInfo& info = m.corners[static_cast<std::size_t>(c.value - 1)];
      info.curves.push_back(id);
      info.patches.insert(info.patches.end(), patches.begin(), patches.end());
    }
  };
  const std::string digits = "01";
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      add_curve(std::string("x") + digits[j] + digits[k],
                {vertex(0, j, k), vertex(1, j, k), vertex(2, j, k)}, corner(0, j, k),
                corner(1, j, k), {PatchId(1), PatchId(2)});
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 2; ++i)
      add_curve(std::string("y") + digits[i] + digits[k],
                {vertex(2 * i, 0, k), vertex(2 * i, 1, k)}, corner(i, 0, k), corner(i, 1, k),
                {PatchId(1 + i)});
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      add_curve(std::string("z") + digits[i] + digits[j],
                {vertex(2 * i, j, 0), vertex(2 * i, j, 1)}, corner(i, j, 0), corner(i, j, 1),
                {PatchId(1 + i)});
  add_curve("rim",
            {vertex(1, 0, 0), vertex(1, 1, 0), vertex(1, 1, 1), vertex(1, 0, 1), vertex(1, 0, 0)},
            CornerId(0), CornerId(0), {PatchId(1), PatchId(2), PatchId(3)});
  for (CornerInfo& c : m.corners) {
    std::sort(c.patches.begin(), c.patches.end());
    c.patches.erase(std::unique(c.patches.begin(), c.patches.end()), c.patches.end());
  }
  return m;
}

/// `m` with every vertex moved by a small irregular amount, so that coordinates
/// are not short decimals (tests full precision); vertex 0 is pulled out
/// further. Keeps the orientation of the two-cube fixtures.
inline TetMesh jittered(TetMesh m) {
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const double k = static_cast<double>(i) + 1;
    m.vertices[i] =
        m.vertices[i] + 1e-3 * Point3{std::sin(k), std::cos(2 * k), std::sin(3 * k) / 3};
  }
  m.vertices[0].x = -1.0 / 3.0;
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
