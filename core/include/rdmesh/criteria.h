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
  /// radius-edge bound 1 / (2 sin angle)); at most 30 for guaranteed termination.
  double facet_angle_deg = 25.0;
  /// R4 approximation: distance between a restricted facet's circumcenter and
  /// its surface Delaunay ball center <= facet_distance.
  double facet_distance = 0.01;
  /// R5.1: circumradius of a tetrahedron <= cell_size(circumcenter).
  ScalarField cell_size = ScalarField::uniform(0.1);
  /// R5.2 (beta_3): circumradius / shortest edge of a tetrahedron; >= 2 for guaranteed termination.
  double cell_radius_edge = 2.0;
  /// Termination guard: a refinement point closer than this to an existing
  /// vertex is not inserted (the element is left as is and counted). 0 selects
  /// 1e-4 of the bounding-box diagonal.
  double min_size = 0.0;

  /// Throws InputError when a bound is non-positive, NaN or out of range.
  void validate() const;
};

/// Defaults derived from the domain's bounding box: size = diagonal / 20 for
/// edges, facets and cells, facet_distance = size / 10.
Criteria default_criteria(const Box3& box);

}  // namespace rdmesh
