// Private to core/: which rule of RR-7912 section 3 an element violates, and by
// how much. Each refinement level (level_curves.h, level_facets.h,
// level_cells.h) reports a Violation for its elements; its priority orders the
// level's queue, worst first.
#pragma once

#include <cstdint>

namespace rdmesh::detail {

/// The rules of RR-7912 section 3, as a level reports them.
enum class Rule : std::uint8_t {
  kNone,
  kR1NotRestricted,  ///< a vertex not on the arc lies in its restricted Delaunay ball
  kR2Size,           ///< the arc's ball is larger than the edge size
  kR2Distance,       ///< the chord is farther than facet_distance from the ball's centre
  kR3NotFaithful,    ///< a vertex of a facet of D|S_k does not lie on S_k (or its boundary)
  kR4Size,           ///< R4.1: the surface Delaunay ball is larger than the facet size
  kR4Shape,          ///< R4.2: the facet's smallest angle is below facet_angle_deg
  kR4Distance,       ///< the facet is farther than facet_distance from its ball's centre
  kR5Size,           ///< R5.1: the Delaunay ball is larger than the cell size
  kR5Shape,          ///< R5.2: the radius-edge ratio exceeds cell_radius_edge
};

/// Priority of the topological rules R1 and R3: above every size or shape
/// ratio, so that those elements are refined first.
inline constexpr double kTopologicalPriority = 1e300;
/// The ratio of a degenerate facet: no shortest edge (R4.2) or no finite
/// distance to its ball's centre; below kTopologicalPriority.
inline constexpr double kDegenerateRatio = 1e200;

/// An element's worst rule and its priority: the ratio by which it exceeds
/// that rule's bound (> 1), or kTopologicalPriority for R1 and R3. No rule:
/// Rule::kNone and priority 0.
struct Violation {
  Rule rule = Rule::kNone;
  double priority = 0.0;

  explicit operator bool() const { return rule != Rule::kNone; }
  /// Keeps `r` when its ratio is larger than the worst so far (the first of equal ones).
  void worsen(Rule r, double ratio) {
    if (ratio > priority) {
      rule = r;
      priority = ratio;
    }
  }
  static Violation topological(Rule r) { return {r, kTopologicalPriority}; }
};

}  // namespace rdmesh::detail
