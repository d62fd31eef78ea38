// Private to core/: the cells incident to a vertex, listed as CGAL's
// Triangulation_3::incident_cells lists them (a depth-first walk from
// v->cell(), each cell once, in the order it is first reached), so that the
// callers' results do not change, but cheaper. CGAL's walk builds a
// std::stack (a std::deque, one allocation) per call; this one keeps its
// stack between calls. And the walk is bound by memory latency, the cells of
// a star lying far apart in a mesh of millions: before looking at a cell's
// neighbours it asks for all of them at once (a prefetch), so that their
// cache misses overlap instead of following one another.
#pragma once

#include <vector>

#include "triangulation_types.h"

namespace rdmesh::detail {

class StarWalk {
 public:
  /// Replaces `out` by the cells incident to v (tr three-dimensional).
  void cells(Vertex_handle v, std::vector<Cell_handle>& out) {
    out.clear();
    const Cell_handle d = v->cell();
    stack_.clear();
    stack_.push_back(d);
    d->tds_data().mark_in_conflict();
    out.push_back(d);
    do {
      const Cell_handle c = stack_.back();
      stack_.pop_back();
      for (int i = 0; i < 4; ++i)
        if (c->vertex(i) != v) __builtin_prefetch(&*c->neighbor(i));
      for (int i = 0; i < 4; ++i) {
        if (c->vertex(i) == v) continue;
        const Cell_handle next = c->neighbor(i);
        if (!next->tds_data().is_clear()) continue;
        stack_.push_back(next);
        next->tds_data().mark_in_conflict();
        out.push_back(next);
      }
    } while (!stack_.empty());
    for (const Cell_handle& c : out) c->tds_data().clear();
  }

 private:
  std::vector<Cell_handle> stack_;
};

}  // namespace rdmesh::detail
