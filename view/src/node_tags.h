// Gmsh node tags -> point indices. Tags are arbitrary positive integers
// (sparse in files written by other tools); a dense table serves tags that are
// close to 1..n, a sorted table the rest, so memory stays proportional to n.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace rdmesh::view::detail {

class NodeTags {
 public:
  /// `tags[i]` is the tag of point i. Returns false when a tag repeats or is < 1.
  bool build(const std::vector<std::int64_t>& tags);
  /// The point index of `tag`, or -1 when no node has it.
  int find(std::int64_t tag) const;

 private:
  std::vector<int> dense_;  ///< dense_[tag] = index or -1
  std::vector<std::pair<std::int64_t, int>> sorted_;
};

}  // namespace rdmesh::view::detail
