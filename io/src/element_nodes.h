// Internal to io/: the node lists of second-order elements in each output
// format's order. TetMesh stores a tetrahedron's mid nodes in Gmsh's order
// (edges 01, 12, 20, 30, 32, 31); VTK's quadratic tetra and Medit's
// TetrahedraP2 (P.L. George's order) take edges 01, 12, 20, 03, 13, 23, i.e.
// the last two swapped. Triangles (01, 12, 20) and lines (ends, then middle)
// are the same in all three formats.
#pragma once

#include <array>
#include <vector>

#include "rdmesh/tet_mesh.h"

namespace rdmesh::io_detail {

enum class Tet10Order { kGmsh, kVtk };

inline std::vector<std::array<int, 10>> tet10_elements(const TetMesh& mesh, Tet10Order order) {
  std::vector<std::array<int, 10>> out(mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& v = mesh.tets[t];
    const auto& m = mesh.tet_mid_nodes[t];
    out[t] = {v[0], v[1], v[2], v[3], m[0], m[1], m[2], m[3], m[4], m[5]};
    if (order == Tet10Order::kVtk) std::swap(out[t][8], out[t][9]);
  }
  return out;
}

inline std::vector<std::array<int, 6>> triangle6_elements(const TetMesh& mesh) {
  std::vector<std::array<int, 6>> out(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& v = mesh.triangles[f];
    const auto& m = mesh.triangle_mid_nodes[f];
    out[f] = {v[0], v[1], v[2], m[0], m[1], m[2]};
  }
  return out;
}

inline std::vector<std::array<int, 3>> line3_elements(const TetMesh& mesh) {
  std::vector<std::array<int, 3>> out(mesh.edges.size());
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    out[e] = {mesh.edges[e][0], mesh.edges[e][1], mesh.edge_mid_nodes[e]};
  }
  return out;
}

}  // namespace rdmesh::io_detail
