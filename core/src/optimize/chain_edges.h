// Private to core/: the edges of D|L (consecutive samples of each curve, and a
// corner with the first or last sample of each curve at it). Sliver exudation
// must keep every one of them as a mesh edge; other edges between feature
// vertices may change.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "../triangulation_types.h"

namespace rdmesh::detail {

class ChainEdges {
 public:
  void add(Vertex_handle a, Vertex_handle b) { edges_.push_back(key(a, b)); }
  /// Call once after the last add().
  void finish() {
    std::sort(edges_.begin(), edges_.end());
    edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
  }
  bool contains(Vertex_handle a, Vertex_handle b) const {
    return std::binary_search(edges_.begin(), edges_.end(), key(a, b));
  }
  bool empty() const { return edges_.empty(); }

 private:
  using Key = std::pair<const void*, const void*>;
  static Key key(Vertex_handle a, Vertex_handle b) {
    const void* p = &*a;
    const void* q = &*b;
    return p < q ? Key{p, q} : Key{q, p};
  }
  std::vector<Key> edges_;
};

}  // namespace rdmesh::detail
