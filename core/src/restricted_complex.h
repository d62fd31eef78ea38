// Private to core/: the restricted complex of RR-7912 section 3 over the
// triangulation D(P) it owns, maintained cell by cell:
//  - D|O: a cell's label is the subdomain of its circumcenter (orthocenter
//    next to protecting balls), from the oracle;
//  - D|S_k: a facet is restricted to patch S_k when its dual Voronoi edge
//    crosses S_k; the crossing is the center of its surface Delaunay ball.
// The rules that read it live in the levels (level_facets.h, level_cells.h);
// the curves' D|L_j in restricted_curves.h.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

#include "rdmesh/oracle.h"
#include "triangulation_types.h"

namespace rdmesh::detail {

class RestrictedComplex {
 public:
  /// `surface_only`: no cell is labelled and every dual edge is asked (an
  /// open patch has no sides).
  RestrictedComplex(const DomainOracle& oracle, bool surface_only);

  Triangulation& triangulation() { return tr_; }
  const Triangulation& triangulation() const { return tr_; }
  bool surface_only() const { return surface_only_; }

  /// The patches bounded by each corner and each curve (index = id - 1), for R3.
  void set_feature_patches(std::vector<std::vector<PatchId>> corner_patches,
                           std::vector<std::vector<PatchId>> curve_patches);
  /// Whether vertex v lies on patch `patch` (on it, or on a curve/corner bounding it).
  bool on_patch(const VertexInfo& v, PatchId patch) const;

  /// Stamps c and computes its orthocenter and label. `from`, when it is a
  /// labeled finite neighbor, lets the oracle label c by a short walk from
  /// its center (DomainOracle::locate with a hint) instead of locating from scratch.
  void init_cell(Cell_handle c, Cell_handle from = Cell_handle());
  /// Initializes every cell not stamped yet (after the initial points):
  /// labels spread from cell to neighboring cell, the first cell of each
  /// connected sweep is located from scratch.
  void init_unstamped_cells();
  /// Recomputes facet (c, i)'s restricted status on both sides; true when it
  /// belongs to D|S (its patch and surface centre are then set).
  bool update_facet(Cell_handle c, int i);
  /// The dual Voronoi edge of facet (c, i), clipped to the enlarged box.
  bool dual_segment(Cell_handle c, int i, Point3& a, Point3& b) const;
  /// The power |x - p|^2 - w of x with respect to the facet's first vertex:
  /// the squared radius of the surface Delaunay ball centred at x.
  double facet_power(Cell_handle c, int i, const Point3& x) const;

  /// The stamp the next initialized cell gets (stamps only grow).
  std::uint32_t next_stamp() const { return next_stamp_; }
  /// Whether the cell stamped `stamp` still exists. (An atomic load, a plain
  /// one on x86: refinement lanes read it while others mark their cells.)
  bool is_live(std::uint32_t stamp) const {
    auto& word = const_cast<std::uint64_t&>(live_[stamp >> 6]);
    return (std::atomic_ref<std::uint64_t>(word).load(std::memory_order_relaxed) >> (stamp & 63)) &
           1;
  }
  /// Marks a cell about to be destroyed: its stamp becomes dead.
  void kill(CellInfo& c);

  /// A refinement lane's own stamps (refinement_lanes.h): [next, end).
  struct StampBlock {
    std::uint32_t next = 0;
    std::uint32_t end = 0;
    std::uint32_t left() const { return end - next; }
  };
  /// Hands out the next blocks.size() runs of `each` stamps, one per lane,
  /// with room for their live bits; next_stamp() passes them all.
  void reserve_stamp_blocks(std::uint32_t each, std::vector<StampBlock>& blocks);
  /// init_cell() with a stamp from `block`, marked live by an atomic write:
  /// lanes initialize cells at once (their bits may share a word).
  void init_cell_in_lane(Cell_handle c, Cell_handle from, StampBlock& block);
  /// kill() by an atomic write, for a lane.
  void kill_in_lane(CellInfo& c);

 private:
  /// Gives c the next stamp and marks it live.
  void stamp_new(CellInfo& c);
  /// init_cell() once c is stamped.
  void label_cell(Cell_handle c, Cell_handle from);
  /// The crossing init_cell() kept for facet (c, i), when it was found against
  /// the present neighbor n; forgotten either way.
  std::optional<SurfaceHit> take_crossing(Cell_handle c, int i, Cell_handle n);

  const DomainOracle& oracle_;
  bool surface_only_;
  Box3 clip_box_;  ///< oracle box with a margin: rays are clipped to it
  Triangulation tr_;
  std::uint32_t next_stamp_ = 1;
  std::vector<std::uint64_t> live_;                   ///< bit s: the cell stamped s still exists
  std::vector<std::vector<PatchId>> curve_patches_;   ///< index = CurveId - 1
  std::vector<std::vector<PatchId>> corner_patches_;  ///< index = CornerId - 1
};

}  // namespace rdmesh::detail
