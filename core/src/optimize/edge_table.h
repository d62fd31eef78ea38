// Private to core/: the edges of a triangulated surface given facet by facet,
// each with the facets that hold it. The exudation re-triangulates a zone as
// the cone from one vertex over the zone's boundary, which is valid only when
// that boundary is a closed surface: every edge on exactly two facets. The
// weight pump and the vertex perturber both check it here, and look up the
// two facets of an edge.
//
// An open-addressing table keyed by the two vertices (by address: the key only
// decides where an edge is kept, never an answer), emptied in constant time by
// a generation count, so that the thousands of zones of an exudation reuse one
// table.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "../triangulation_types.h"

namespace rdmesh::detail {

/// An order of vertices that only serves to name an edge once ({a, b}, a < b).
inline bool vertex_less(Vertex_handle a, Vertex_handle b) { return &*a < &*b; }

class EdgeTable {
 public:
  /// An edge ab (vertex_less(a, b)) and the first two facets that hold it.
  struct Edge {
    Vertex_handle a, b;
    int facet[2] = {-1, -1};
    int count = 0;  ///< how many facets hold it
    std::uint32_t gen = 0;
  };

  /// Empties the table, with room for `edges` edges.
  void reset(std::size_t edges);
  /// Records that facet `facet` holds the edge of vertices a and b (either order).
  void add(Vertex_handle a, Vertex_handle b, int facet);
  /// Whether some facet holds the edge of vertices a and b (either order).
  bool contains(Vertex_handle a, Vertex_handle b) const;
  /// The edges added since reset(), in order of first addition.
  std::size_t size() const { return used_.size(); }
  const Edge& operator[](std::size_t k) const { return slots_[used_[k]]; }

 private:
  /// The slot of ab (vertex_less(a, b)): its own, or the empty one it would take.
  std::size_t slot(Vertex_handle a, Vertex_handle b) const;

  std::vector<Edge> slots_;          ///< a power of two of them, at most half full
  std::vector<std::uint32_t> used_;  ///< occupied slots, in order of first use
  std::uint32_t gen_ = 0;            ///< a slot is occupied when its gen is this
};

}  // namespace rdmesh::detail
