// CurvePiece: sub-ranges of a curve, wrapping around the seam of a closed one.
#include "curve_piece.h"

#include <algorithm>

namespace rdmesh::detail {

CurvePiece::CurvePiece(std::shared_ptr<const Curve> base, double base_begin, double base_end,
                       double begin, double end, Point3 start_point, Point3 end_point)
    : base_(std::move(base)),
      base_begin_(base_begin),
      base_end_(base_end),
      period_(base_end - base_begin),
      begin_(begin),
      end_(end),
      start_point_(start_point),
      end_point_(end_point) {}

Point3 CurvePiece::point(double t) const {
  if (t <= begin_) return start_point_;
  if (t >= end_) return end_point_;
  return base_->point(t > base_end_ ? t - period_ : t);
}

double CurvePiece::length(double ta, double tb) const {
  ta = clamp(ta), tb = clamp(tb);
  if (ta > tb) return -length(tb, ta);
  if (tb <= base_end_) return base_->length(ta, tb);
  if (ta >= base_end_) return base_->length(ta - period_, tb - period_);
  return base_->length(ta, base_end_) + base_->length(base_begin_, tb - period_);
}

double CurvePiece::parameter_at_length(double ta, double s) const {
  ta = clamp(ta);
  if (!(s > 0)) return ta;
  if (ta >= base_end_) return clamp(base_->parameter_at_length(ta - period_, s) + period_);
  if (end_ <= base_end_) return clamp(base_->parameter_at_length(ta, s));
  const double first = base_->length(ta, base_end_);
  if (s <= first) return std::min(base_->parameter_at_length(ta, s), base_end_);
  return clamp(base_->parameter_at_length(base_begin_, s - first) + period_);
}

double CurvePiece::closest(const Point3& p, double ta, double tb) const {
  ta = clamp(ta), tb = clamp(tb);
  if (!(ta < tb)) return ta;
  if (tb <= base_end_) return base_->closest(p, ta, tb);
  if (ta >= base_end_) return base_->closest(p, ta - period_, tb - period_) + period_;
  const double t1 = base_->closest(p, ta, base_end_);
  const double t2 = base_->closest(p, base_begin_, tb - period_) + period_;
  return squared_norm(point(t1) - p) <= squared_norm(point(t2) - p) ? t1 : t2;
}

std::vector<double> CurvePiece::plane_crossings(const Point3& normal, double offset, double ta,
                                                double tb) const {
  ta = clamp(ta), tb = clamp(tb);
  if (!(ta < tb)) return {};
  if (tb <= base_end_) return base_->plane_crossings(normal, offset, ta, tb);
  std::vector<double> out;
  if (ta < base_end_) out = base_->plane_crossings(normal, offset, ta, base_end_);
  const double from = std::max(ta, base_end_) - period_;
  for (double t : base_->plane_crossings(normal, offset, from, tb - period_)) {
    if (out.empty() || t + period_ > out.back()) out.push_back(t + period_);
  }
  return out;
}

double CurvePiece::curvature(double t) const {
  t = clamp(t);
  return base_->curvature(t > base_end_ ? t - period_ : t);
}

}  // namespace rdmesh::detail
