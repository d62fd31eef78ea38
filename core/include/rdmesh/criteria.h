// Mesh criteria: the sizing field sigma and shape bounds of RR-7912, section 3.
#pragma once

#include "rdmesh/geometry.h"

namespace rdmesh {

/// The rules' parameters. Sizes are absolute lengths.
struct Criteria {
  /// R2: radius of a restricted edge's Delaunay ball (centered on the curve) <= edge_size(center).
  /// The chord of each restricted edge also stays within facet_distance of its curve.
  ScalarField edge_size = ScalarField::uniform(0.1);
  /// R4.1: radius of a restricted facet's surface Delaunay ball <= facet_size(center).
  ScalarField facet_size = ScalarField::uniform(0.1);
  /// R4.2: minimum angle of a restricted facet, in degrees (equivalent to a
  /// radius-edge bound 1 / (2 sin angle)); in (0, 30]: above 30 termination is not guaranteed.
  double facet_angle_deg = 25.0;
  /// R4 approximation: distance between a restricted facet's circumcenter and
  /// its surface Delaunay ball center <= facet_distance(ball center). A field, so
  /// that the boundary follows thin parts as closely as their size asks.
  ScalarField facet_distance = ScalarField::uniform(0.01);
  /// R5.1: circumradius of a tetrahedron <= cell_size(circumcenter).
  ScalarField cell_size = ScalarField::uniform(0.1);
  /// R5.2 (beta_3): circumradius / shortest edge of a tetrahedron; >= 2 (RR-7912's bound for
  /// termination).
  double cell_radius_edge = 2.0;
  /// Termination guard: a refinement point closer than this to an existing
  /// vertex is not inserted (the element is left as is and counted). 0 selects
  /// 1e-4 of the bounding-box diagonal.
  double min_size = 0.0;

  /// The minimum size actually used: min_size, or 1e-4 of `box`'s diagonal when it is 0.
  double min_size_for(const Box3& box) const;

  /// Throws InputError when a bound is non-positive, NaN or out of range, when the
  /// radius-edge bound is below 2 or the facet angle above 30 degrees (no termination proof).
  void validate() const;
};

/// The size of the mesh the criteria imply over a box, from the sizes sampled on a
/// 16^3 grid of nodes over the box (its corners included), V and A the box's volume and
/// area, L the total length of the sharp curves, D its diagonal, d the facet distance:
///   tetrahedra = 5 V mean(1 / cell_size^3),
///   triangles  = 2 A mean(1 / s^2), s = min(facet_size, sqrt(D d)) (the facet size a
///                curvature radius D/2 allows at distance d),
///   edges      = L mean(1 / edge_size).
/// Calibrated on samples/cube.json and sphere.json at size 0.1 (4.4 tetrahedra and 1.5 to
/// 1.6 triangles per h^3 of the domain's volume and h^2 of its area); the box bounds the
/// domain, so the estimate is an upper bound up to the constants.
struct ElementEstimate {
  double tetrahedra = 0, triangles = 0, edges = 0;
  double total() const { return tetrahedra + triangles + edges; }
};
ElementEstimate estimate_elements(const Criteria& criteria, const Box3& box, double curve_length);

/// The default limit of check_feasible on the estimated element count.
inline constexpr double kDefaultMaxElements = 50e6;

/// Refuses up front criteria that cannot give a bounded mesh over `box` (InputError with
/// the reason): validate(); every size field, sampled as in estimate_elements, positive,
/// finite and not below the minimum size (naming the first point where it is not); the
/// facet distance not below the minimum size; the estimated element count at most
/// `max_elements` (the message names `--max-elements`, the CLI option that raises it).
void check_feasible(const Criteria& criteria, const Box3& box, double curve_length,
                    double max_elements = kDefaultMaxElements);

/// Defaults derived from the domain's bounding box: size = diagonal / 20 for
/// edges, facets and cells, facet_distance = size / 10.
Criteria default_criteria(const Box3& box);

}  // namespace rdmesh
