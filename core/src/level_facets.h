// Private to core/: the facet level of RR-7912 section 3, rules R3 and R4 on
// the facets of D|S (level_facets.cpp).
//   R3    a vertex of a facet of D|S_k does not lie on S_k (or on a curve or
//         corner bounding it): the surface is not yet faithfully sampled;
//   R4.1  the surface Delaunay ball is larger than the facet size;
//   R4.2  the facet's smallest angle is below facet_angle_deg;
//   and the approximation bound (as CGAL Mesh_3): the facet lies within
//   facet_distance of its ball's centre.
// refine-facet-or-edge inserts the ball's centre, or refines the arc whose
// ball the centre lies in.
#pragma once

#include <cstddef>
#include <optional>
#include <queue>
#include <vector>

#include "element_entry.h"
#include "insertion.h"
#include "lane_cut.h"
#include "rdmesh/criteria.h"
#include "restricted_complex.h"
#include "violation.h"

namespace rdmesh::detail {

class CurveLevel;

class FacetLevel {
 public:
  /// Both must outlive the level.
  FacetLevel(const RestrictedComplex& complex, const Criteria& criteria);

  /// The worst rule facet (c, i) violates; Rule::kNone for a facet not in D|S.
  Violation violation(Cell_handle c, int i) const;
  /// Queues facet (c, i) when it violates a rule.
  void consider(Cell_handle c, int i);

  /// The level's own queue (the sequential steps') is empty.
  bool empty() const { return queue_.empty(); }
  /// Every queued entry, the lanes' and the parked ones too.
  std::size_t size() const {
    return queue_.size() + lanes_[0].size() + lanes_[1].size() + parked_.size();
  }

  /// Refinement lanes (refinement_lanes.h): while on, consider() sends a
  /// facet whose two cells lie in lane k to lane k's queue, unless its surface
  /// ball has a squared radius of `max_squared_radius` or more (its centre's
  /// zone reaches across the cut).
  void set_lanes(bool on, double max_squared_radius, const LaneCut* cut) {
    lanes_on_ = on;
    lane_max_squared_radius_ = max_squared_radius;
    cut_ = cut;
  }
  using Queue = std::priority_queue<ElementEntry>;
  Queue& lane_queue(int lane) { return lanes_[lane]; }
  const Queue& lane_queue(int lane) const { return lanes_[lane]; }
  /// Queues an entry for the sequential steps (one a lane could not refine):
  /// pop() refines it, never hands it back to the lanes.
  void push(ElementEntry e) {
    e.facet += kPinned;
    queue_.push(e);
  }
  /// The entries pop() parked, for the next round of the lanes (which takes them).
  std::vector<ElementEntry>& parked() { return parked_; }
  const std::vector<ElementEntry>& parked() const { return parked_; }
  /// The lane whose queue takes facet (c, i) (both cells in it, a small
  /// surface ball); -1: the sequential steps, or lanes off.
  int lane_of(Cell_handle c, int i) const;
  /// Pops the worst entry: the facet, if it still exists and still violates a
  /// rule; else nullopt: the entry was stale, or, lanes on, the facet's
  /// surface ball is small enough for a lane and push() did not queue it. Such
  /// a facet goes to the lane that owns both its cells now (they were refined,
  /// or the cut moved, since it was queued), or is parked for the next round's
  /// cut (parked()), as CellLevel::pop does.
  std::optional<ElementEntry> pop();

  /// refine-facet-or-edge for facet (c, i): consider the centre c_f of its
  /// surface Delaunay ball; if it lies in the ball of an arc, refine that arc,
  /// else insert c_f (unless the curve level keeps it out). Whether a point
  /// was inserted.
  bool refine(Cell_handle c, int i, Insertion& insertion, CurveLevel& curves);
  /// The largest surface Delaunay ball of the facets of `zone` containing x:
  /// true, with that facet, when there is one. (A surface ball lies in the
  /// union of its facet's two Delaunay balls, so a ball containing a point
  /// belongs to a facet of the point's conflict zone.)
  bool encroached(const Point3& x, const std::vector<Cell_handle>& zone, Cell_handle& cell,
                  int& facet) const;

 private:
  /// Added to ElementEntry::facet by push().
  static constexpr int kPinned = 8;
  /// Lanes on and the surface ball of facet (c, i) small enough for a lane.
  bool fits_lane(Cell_handle c, int i) const;
  /// The lane that owns both cells of facet (c, i), or -1.
  int owner(Cell_handle c, int i) const;

  const RestrictedComplex& complex_;
  const Criteria& criteria_;
  double shape_bound_;  ///< 4 sin^2(facet angle): min edge^2 / R^2 below it is bad
  Queue queue_;
  Queue lanes_[2];
  std::vector<ElementEntry> parked_;
  bool lanes_on_ = false;
  double lane_max_squared_radius_ = 0;
  const LaneCut* cut_ = nullptr;  ///< the lanes' current cut (RefinementLanes)
};

}  // namespace rdmesh::detail
