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
#include <vector>

#include "bucket_queue.h"
#include "element_entry.h"
#include "insertion.h"
#include "lane_cell_queue.h"
#include "lane_cut.h"
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
  /// Queues cell c when it violates a rule: in the queue of the refinement
  /// lane that owns it when lanes are on (set_lanes), else in the level's.
  void consider(Cell_handle c);

  /// The level's own queue (the sequential steps') is empty.
  bool empty() const { return queue_.empty(); }
  /// Every queued entry, the lanes' and the parked ones too.
  std::size_t size() const {
    return queue_.size() + lanes_[0].size() + lanes_[1].size() + parked_.size();
  }

  /// Refinement lanes (refinement_lanes.h): while on, consider() sends a cell
  /// all of whose vertices hold lane k's bit to lane k's queue.
  /// Cells whose ball has a squared radius of `max_squared_radius` or more
  /// stay in the level's queue: their zones reach across the cut.
  void set_lanes(bool on, double max_squared_radius, const LaneCut* cut) {
    lanes_on_ = on;
    lane_max_squared_radius_ = max_squared_radius;
    cut_ = cut;
  }
  LaneCellQueue& lane_queue(int lane) { return lanes_[lane]; }
  const LaneCellQueue& lane_queue(int lane) const { return lanes_[lane]; }
  /// Queues an entry for the sequential steps (one a lane could not refine):
  /// pop() refines it, never hands it back to the lanes.
  void push(ElementEntry e) {
    e.facet = kPinned;
    queue_.push(bucket_of(e.priority), e);
  }
  /// The entries pop() parked, for the next round of the lanes (which takes them).
  std::vector<ElementEntry>& parked() { return parked_; }
  const std::vector<ElementEntry>& parked() const { return parked_; }
  /// The entry of cell c for `v`, its violation.
  static ElementEntry entry(Cell_handle c, const Violation& v) {
    return {v.priority, c, c->info().stamp, -1};
  }
  /// The queue bucket of a priority.
  static std::size_t bucket_of(double priority);
  /// Pops the worst entry: the cell, if it still exists and still violates a
  /// rule; else nullopt: the entry was stale, or, lanes on, the cell is small
  /// enough for a lane and push() did not queue it. Such a cell goes to the
  /// lane that owns it now (the cut moved since it was queued), or is parked
  /// for the next round's cut (parked()): refining it here would refine the
  /// whole layer of cells along the cut on one thread.
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
    for (LaneCellQueue& q : lanes_)
      if (q.empty()) q.release();
  }

 private:
  /// ElementEntry::facet of an entry push() queued (-1 for the others).
  static constexpr int kPinned = -3;
  /// Lanes on and cell c's ball small enough for a lane.
  bool fits_lane(Cell_handle c) const;
  /// The lane that owns all four vertices of c, or -1.
  int owner(Cell_handle c) const;

  const RestrictedComplex& complex_;
  const Criteria& criteria_;
  double shape_bound_sq_;  ///< beta_3^2
  BucketQueue<ElementEntry> queue_;
  std::vector<ElementEntry> parked_;
  LaneCellQueue lanes_[2];
  bool lanes_on_ = false;
  double lane_max_squared_radius_ = 0;
  const LaneCut* cut_ = nullptr;  ///< the lanes' current cut (RefinementLanes)
};

}  // namespace rdmesh::detail
