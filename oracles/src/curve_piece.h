// CurvePiece: the sub-range [begin, end] of a base curve, as handed out by
// ImplicitOracle::curve() after curves were split at their meeting points.
//
// For a closed base curve on [base_begin, base_end] a piece may wrap around the
// seam: end > base_end, and a parameter u > base_end means u - period on the
// base. The end points are snapped: point(begin) and point(end) return exactly
// the given start/end points (the corners), so that endpoints and corners agree
// bit for bit. Everything else forwards to the base curve; const and thread-safe
// when the base curve is.
#pragma once

#include <memory>
#include <vector>

#include "rdmesh/curve.h"

namespace rdmesh::detail {

class CurvePiece final : public Curve {
 public:
  CurvePiece(std::shared_ptr<const Curve> base, double base_begin, double base_end, double begin,
             double end, Point3 start_point, Point3 end_point);

  double begin() const { return begin_; }
  double end() const { return end_; }

  Point3 point(double t) const override;
  double length(double ta, double tb) const override;
  double parameter_at_length(double ta, double s) const override;
  double closest(const Point3& p, double ta, double tb) const override;
  std::vector<double> plane_crossings(const Point3& normal, double offset, double ta,
                                      double tb) const override;
  double curvature(double t) const override;

 private:
  double clamp(double t) const { return t < begin_ ? begin_ : (t > end_ ? end_ : t); }

  std::shared_ptr<const Curve> base_;
  double base_begin_, base_end_, period_;
  double begin_, end_;
  Point3 start_point_, end_point_;
};

}  // namespace rdmesh::detail
