// A polygonal curve through given points, parameterised by arc length.
//
// Parameter t in [0, L] is the arc length from the first point (so length(ta, tb)
// == tb - ta exactly). The polyline is closed when its first and last points are
// equal (exactly). Immutable after construction: every query is const,
// thread-safe and allocation-free except plane_crossings' result.
#pragma once

#include <vector>

#include "rdmesh/curve.h"

namespace rdmesh {

class PolylineCurve final : public Curve {
 public:
  /// Consecutive duplicate points are dropped. Throws InputError for a non-finite
  /// point or fewer than two distinct points (three for a closed polyline).
  explicit PolylineCurve(std::vector<Point3> points);

  double t_begin() const { return 0.0; }
  double t_end() const { return cumulative_.back(); }
  bool closed() const { return closed_; }
  /// The vertices (without the dropped duplicates).
  const std::vector<Point3>& points() const { return points_; }

  /// Linear interpolation on the segment containing t (clamped to [0, L]).
  Point3 point(double t) const override;
  /// tb - ta, after clamping both to [0, L].
  double length(double ta, double tb) const override;
  /// min(ta + s, L) (ta clamped, s <= 0 gives ta).
  double parameter_at_length(double ta, double s) const override;
  /// Exact: the closest point over the segments meeting [ta, tb] (first one on ties).
  double closest(const Point3& p, double ta, double tb) const override;
  /// Exact up to rounding: one parameter per sign change of dot(normal, x) - offset
  /// along the polyline (a vertex on the plane counts once; a segment lying in the
  /// plane gives its start).
  std::vector<double> plane_crossings(const Point3& normal, double offset, double ta,
                                      double tb) const override;
  /// Discrete: at each inner vertex (every vertex of a closed polyline) the
  /// curvature of the circle through it and its two neighbours (exact for
  /// points on a circle), linear in t between vertices; an open polyline's
  /// ends take their neighbour's value (0 with two points).
  double curvature(double t) const override;

 private:
  std::size_t segment_of(double t) const;
  double clamp(double t) const;

  std::vector<Point3> points_;
  std::vector<double> cumulative_;  // arc length at each vertex
  std::vector<double> vertex_curvature_;
  bool closed_ = false;
};

}  // namespace rdmesh
