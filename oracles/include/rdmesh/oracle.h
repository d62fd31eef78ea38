// The oracle interface: the only way the refinement core sees the geometry.
//
// An oracle describes the input complex F = Q u L u S u C of RR-7912 (section 2):
// subdomains (cells C_l), patches (S_k) separating two subdomains (or a
// subdomain and the outside), curves (L_j) and corners (Q). Every query is
// const and must be thread-safe (no hidden mutable state shared between calls).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rdmesh/curve.h"
#include "rdmesh/geometry.h"

namespace rdmesh {

struct SubdomainInfo {
  SubdomainId id;
  std::string name;
};

/// A surface patch S_k: the boundary between subdomains `side_a` < `side_b`
/// (side_a may be kOutside).
struct PatchInfo {
  PatchId id;
  std::string name;
  SubdomainId side_a;
  SubdomainId side_b;
};

/// A point where a segment crosses a patch.
struct SurfaceHit {
  Point3 point;
  PatchId patch;
};

/// A point whose label is known: the hint that lets locate() walk from it.
struct LocateHint {
  Point3 point;
  SubdomainId label;  ///< what locate(point).label is
};

/// What locate() found: the label, and the crossing of [p, hint] that decided it.
struct Located {
  Located(SubdomainId l, std::optional<SurfaceHit> c = std::nullopt) : label(l), crossing(c) {}
  SubdomainId label;
  std::optional<SurfaceHit> crossing;
};

class DomainOracle {
 public:
  virtual ~DomainOracle() = default;

  /// A box containing the whole domain: locate(p).label == kOutside for every p outside it.
  virtual Box3 bounding_box() const = 0;

  /// Where p is: the subdomain containing it (kOutside, 0, outside the
  /// domain), and, when a hint led there across a patch, that crossing.
  ///
  /// `hint`, when given, is a point whose label is known (what locate() of it
  /// returns). The refiner labels each new cell from a labeled neighbor's
  /// center this way: oracles whose plain locate() casts rays across the whole
  /// domain answer instead by one short query along [p, hint->point]. An
  /// oracle that found the label by such a crossing returns it as `crossing`
  /// (a hit that meets intersect()'s guarantee for [p, hint->point]): the
  /// refiner then reuses it for the facet whose dual edge is that segment
  /// instead of calling intersect() on it again. With or without a hint the
  /// label is the same (up to rounding where the segment passes through a
  /// patch's boundary); an oracle without a cheaper walk ignores the hint and
  /// returns no crossing. Overrides repeat the default argument.
  virtual Located locate(const Point3& p,
                         const std::optional<LocateHint>& hint = std::nullopt) const = 0;

  /// A crossing of segment [a, b] with a patch. Guarantee: whenever
  /// locate(a) != locate(b) a hit is returned, its point lies on the segment
  /// within tolerance() of the patch, and its patch separates two labels met
  /// along the segment. When locate(a) == locate(b) it may return nullopt even
  /// if the segment crosses the boundary an even number of times.
  ///
  /// The default bisects [a, b] on locate() down to tolerance() and returns the
  /// first listed patch between the two labels it ends between: exact up to
  /// tolerance() for any locate(), at about log2(|b - a| / tolerance()) calls
  /// of it (and one of patches()). Override it where a closed form or a root
  /// finder on the geometry is faster, as the built-in oracles do.
  virtual std::optional<SurfaceHit> intersect(const Point3& a, const Point3& b) const;

  /// All subdomains, ids 1..n in order.
  virtual std::vector<SubdomainInfo> subdomains() const = 0;

  /// All patches that exist in the domain, ids ascending.
  virtual std::vector<PatchInfo> patches() const = 0;

  /// Points on `patch` (within tolerance()), at least three on each of its
  /// connected components (RR-7912 starts with >= 3 points per patch).
  virtual std::vector<Point3> initial_points(PatchId patch) const = 0;

  /// The point of `patch` closest to p, for p near the patch (a fraction of the
  /// local feature size away). nullopt when the projection does not converge.
  /// Used to measure the Hausdorff distance of the output, not by refinement.
  virtual std::optional<Point3> project(const Point3& p, PatchId patch) const = 0;

  /// The distance from p to the nearest patch not listed in `patches`, when it
  /// is below `limit`; `limit` otherwise. The protecting balls' planner asks it
  /// to keep the ball of a corner or curve off the patches that feature does
  /// not bound: rule R3 cannot be met where such a patch crosses a ball, and
  /// refinement would find it late and start again with a smaller ball. The
  /// default knows nothing and returns `limit` (refinement then finds those
  /// balls itself); an override may err towards `limit` where it cannot tell.
  virtual double distance_to_other_patches(const Point3& p, const std::vector<PatchId>& patches,
                                           double limit) const {
    (void)p;
    (void)patches;
    return limit;
  }

  /// The largest principal curvature of `patch` in absolute value (1 / the
  /// smallest radius of curvature; 0 on a plane) near p, a point on or near
  /// the patch (as for project()), for sizes that follow it (--curvature).
  /// nullopt where the oracle cannot tell (a pole, a failed projection). The
  /// built-in oracles answer it from their exact geometry; the default knows
  /// nothing, and sizes by curvature then follow the curves only.
  virtual std::optional<double> curvature(const Point3& p, PatchId patch) const {
    (void)p;
    (void)patch;
    return std::nullopt;
  }

  /// Absolute accuracy of the points returned by intersect(), initial_points() and project().
  virtual double tolerance() const = 0;

  // --- Sharp features: curves L and corners Q ---
  //
  // Part of the input complex the mesh conforms to (protecting balls, or the
  // paper's rules R1-R2 on the curves). A smooth domain has none and overrides
  // none of the three: the defaults say so. An oracle with features overrides
  // all three, and may keep them in a FeatureTable (rdmesh/feature_table.h),
  // as the built-in oracles do. Defaults rather than a separate "features"
  // base class: one interface to implement and to pass around, no cast to ask
  // whether a domain has curves (an empty list says it), and the refiner's
  // code reads the same for smooth and sharp domains.

  /// All corners, ids 1..n in order. Default: none.
  virtual std::vector<CornerInfo> corners() const { return {}; }

  /// All curves, ids 1..n in order. Default: none.
  virtual std::vector<CurveInfo> curves() const { return {}; }

  /// Exact queries on curve `id`; throws OracleError for an id outside 1..n
  /// (the default has no curve, so it always throws).
  virtual const Curve& curve(CurveId id) const;
};

}  // namespace rdmesh
