// Private to core/: the cell level of RR-7912 section 3, rule R5 on the cells
// of D|O (level_cells.cpp).
//   R5.1  the Delaunay ball (orthoball next to protecting balls) is larger
//         than the cell size;
//   R5.2  the radius-edge ratio exceeds cell_radius_edge (beta_3).
// refine-tet-facet-or-edge inserts the centre, or refines the arc or the
// facet whose ball the centre lies in.
#pragma once

#include <cstddef>
#include <optional>

#include "bucket_queue.h"
#include "element_entry.h"
#include "insertion.h"
#include "rdmesh/criteria.h"
#include "restricted_complex.h"
#include "violation.h"

namespace rdmesh::detail {

class CurveLevel;
class FacetLevel;

class CellLevel {
 public:
  /// Both must outlive the level.
  CellLevel(const RestrictedComplex& complex, const Criteria& criteria);

  /// The worst rule cell c violates; Rule::kNone outside the domain.
  Violation violation(Cell_handle c) const;
  /// Queues cell c when it violates a rule.
  void consider(Cell_handle c);

  bool empty() const { return queue_.empty(); }
  std::size_t size() const { return queue_.size(); }
  /// Pops the worst entry: the cell, if it still exists and still violates a
  /// rule; else nullopt (the entry was stale).
  std::optional<ElementEntry> pop();

  /// refine-tet-facet-or-edge for the popped entry's cell: consider its
  /// centre c_t; if it lies in the ball of an arc, refine that arc, else if it
  /// lies in the surface ball of a facet, refine that facet (the cell is
  /// queued again), else insert c_t. Whether a point was inserted.
  bool refine(const ElementEntry& entry, Insertion& insertion, CurveLevel& curves,
              FacetLevel& facets);
  /// Frees the queue's storage once it is empty (its peak size is no longer needed).
  void release_if_empty() {
    if (queue_.empty()) queue_.release();
  }

 private:
  const RestrictedComplex& complex_;
  const Criteria& criteria_;
  double shape_bound_sq_;  ///< beta_3^2
  BucketQueue<ElementEntry> queue_;
};

}  // namespace rdmesh::detail
