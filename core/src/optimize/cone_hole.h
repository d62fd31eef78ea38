// Re-triangulating a hole as the cone from an existing vertex.
//
// Exudation changes a vertex's weight (or, perturbing, its position) in place:
// the cells the new point conflicts with form a hole around the vertex, and the
// hole is re-triangulated as the cone from that same vertex, so that its handle,
// its info (feature, curve parameter, ball) and every queue entry naming it stay
// valid. Removal followed by insertion would create a new vertex.
//
// The cone is built here rather than by the data structure's insert_in_hole,
// for two reasons: it reuses the hole's own cells for the first new cells (most
// cones have no more cells than their hole: exudation removes cells), and it
// takes any further cell from, and leaves any spare cell to, a CellPool when
// given one. Two exudation lanes (sliver_exuder.cpp) then re-triangulate their
// own parts of one triangulation at once without touching its cell container,
// which is not thread-safe. tests/core/cone_hole_test.cpp checks the result
// against a regular triangulation built from scratch.
#pragma once

#include <vector>

#include "../triangulation_types.h"
#include "edge_table.h"

namespace rdmesh::detail {

/// Cells held apart from the triangulation, for cone_hole. Filled and released
/// by one thread while nobody else uses the triangulation's container; taken
/// from and given back by the thread of the lane that owns the pool.
class CellPool {
 public:
  explicit CellPool(Triangulation& tr) : tr_(tr) {}
  CellPool(const CellPool&) = delete;
  CellPool& operator=(const CellPool&) = delete;
  ~CellPool() { release(); }

  /// Creates cells in the triangulation's container until the pool holds n.
  void fill(std::size_t n);
  /// Deletes the pooled cells from the container (in the order they were pooled).
  void release();

  std::size_t size() const { return cells_.size(); }
  Cell_handle take();
  void give(Cell_handle c) { cells_.push_back(c); }

 private:
  Triangulation& tr_;
  std::vector<Cell_handle> cells_;
};

/// A facet of a hole's boundary seen from inside: cell `inner` of the hole, and
/// the index of the facet in it.
struct HoleFacet {
  Cell_handle inner;
  int index;
};

/// Builds cones (its scratch is kept from one call to the next).
class ConeBuilder {
 public:
  /// Replaces the cells of `hole` by the cone from v over the hole's boundary
  /// `boundary` (every facet of it once, seen from inside; the hole's union is
  /// star-shaped from v's new point and its boundary a closed surface holding
  /// every vertex of the hole but v). New cell k is boundary[k]'s inner cell
  /// with the vertex opposite the facet replaced by v (the same vertex order),
  /// listed in `created`; its info is default (the caller sets it). The first
  /// new cells reuse the hole's cells; further ones come from `pool`, and spare
  /// hole cells go to it (without a pool: the triangulation's container). The
  /// caller sets v's new point afterwards.
  void build(Triangulation& tr, const std::vector<Cell_handle>& hole,
             const std::vector<HoleFacet>& boundary, Vertex_handle v, CellPool* pool,
             std::vector<Cell_handle>& created);

 private:
  struct Planned {
    Vertex_handle vertices[4];
    Cell_handle outer;
    int outer_index;
    int apex;  ///< index of v
  };
  std::vector<Planned> planned_;
  EdgeTable edges_;
};

}  // namespace rdmesh::detail
