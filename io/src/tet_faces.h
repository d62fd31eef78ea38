// The faces shared by two tetrahedra of a mesh, found by sorting every
// tetrahedron's faces (partition.cpp's dual graph, partition_boundaries.cpp's
// faces between partitions).
#pragma once

#include <algorithm>
#include <array>
#include <tuple>
#include <vector>

#include "rdmesh/tet_mesh.h"

namespace rdmesh::io_detail {

/// A face of tetrahedron `tet`: its vertices sorted, and the tetrahedron's
/// vertex it leaves out (its slot, 0..3).
struct TetFace {
  std::array<int, 3> v;
  int tet, skip;
};

/// Calls f(a, b) for each face two tetrahedra share (a.tet < b.tet), in the
/// order of the faces' sorted vertices.
template <class F>
void for_each_shared_face(const TetMesh& mesh, F f) {
  std::vector<TetFace> faces;
  faces.reserve(4 * mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> v{};
      for (int i = 0, k = 0; i < 4; ++i) {
        if (i != skip) v[k++] = mesh.tets[t][i];
      }
      std::sort(v.begin(), v.end());
      faces.push_back({v, static_cast<int>(t), skip});
    }
  }
  std::sort(faces.begin(), faces.end(), [](const TetFace& a, const TetFace& b) {
    return std::tie(a.v, a.tet) < std::tie(b.v, b.tet);
  });
  for (std::size_t i = 0; i + 1 < faces.size(); ++i) {
    if (faces[i].v == faces[i + 1].v) f(faces[i], faces[i + 1]);
  }
}

}  // namespace rdmesh::io_detail
