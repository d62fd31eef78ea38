// Faces of a set of tetrahedra that belong to one tetrahedron of the set only:
// the boundary of the set, which is all that can be seen of it.
#pragma once

#include <cstdint>
#include <vector>

#include "rdmesh/view_mesh.h"

namespace rdmesh::view::detail {

/// A face of tetrahedron `tet`: the one opposite its vertex `local` (0..3).
struct TetFace {
  std::uint32_t tet;
  std::uint32_t local;
};

/// The faces of the tetrahedra t with keep[t] != 0 (all when `keep` is empty)
/// that no other kept tetrahedron shares, in increasing (tet, local) order.
/// Linear time: faces are bucketed by their smallest vertex, then matched
/// within the bucket.
std::vector<TetFace> exposed_faces(const ViewMesh& mesh, const std::vector<char>& keep);

}  // namespace rdmesh::view::detail
