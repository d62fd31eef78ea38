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

class DomainOracle {
 public:
  virtual ~DomainOracle() = default;

  /// A box containing the whole domain: locate(p) == kOutside for every p outside it.
  virtual Box3 bounding_box() const = 0;

  /// Label of the subdomain containing p, kOutside (0) when p is outside the domain.
  virtual SubdomainId locate(const Point3& p) const = 0;

  /// locate(p), given a point `known` whose label is `known_label` (what
  /// locate(known) returns). The refiner labels a new cell from a labeled
  /// neighbor this way. Oracles whose locate() casts rays across the whole
  /// domain override it with one short query along [p, known]; the default
  /// ignores the hint.
  virtual SubdomainId locate_from(const Point3& p, const Point3& known,
                                  SubdomainId known_label) const {
    (void)known;
    (void)known_label;
    return locate(p);
  }

  /// locate_from(p, known, known_label), and the crossing of [p, known] that
  /// decided it when the oracle found one: a hit that meets intersect()'s
  /// guarantee for that segment. The refiner labels a new cell from a
  /// neighbor's center and then needs a crossing of the very same segment (the
  /// dual edge of the facet between them) when their labels differ; an oracle
  /// that answers locate_from() by a crossing hands it over here. The default
  /// returns none, and the refiner calls intersect().
  struct Located {
    SubdomainId label;
    std::optional<SurfaceHit> crossing;
  };
  virtual Located locate_across(const Point3& p, const Point3& known,
                                SubdomainId known_label) const {
    return {locate_from(p, known, known_label), std::nullopt};
  }

  /// A crossing of segment [a, b] with a patch. Guarantee: whenever
  /// locate(a) != locate(b) a hit is returned, its point lies on the segment
  /// within tolerance() of the patch, and its patch separates two labels met
  /// along the segment. When locate(a) == locate(b) it may return nullopt even
  /// if the segment crosses the boundary an even number of times.
  virtual std::optional<SurfaceHit> intersect(const Point3& a, const Point3& b) const = 0;

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

  // --- Sharp features: curves L and corners Q (empty for a smooth domain) ---

  /// All corners, ids 1..n in order.
  virtual std::vector<CornerInfo> corners() const = 0;

  /// All curves, ids 1..n in order.
  virtual std::vector<CurveInfo> curves() const = 0;

  /// Exact queries on curve `id`; throws OracleError for an unknown id.
  virtual const Curve& curve(CurveId id) const = 0;
};

}  // namespace rdmesh
