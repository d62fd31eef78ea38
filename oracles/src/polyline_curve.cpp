// PolylineCurve: exact queries on a polygonal curve (rdmesh/polyline_curve.h).
#include "rdmesh/polyline_curve.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "rdmesh/errors.h"

namespace rdmesh {

PolylineCurve::PolylineCurve(std::vector<Point3> points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point3& p = points[i];
    if (!is_finite(p)) {
      throw InputError("point " + std::to_string(i) + " is not finite");
    }
    if (points_.empty() || !(points_.back() == p)) points_.push_back(p);
  }
  closed_ = points_.size() > 1 && points_.front() == points_.back();
  if (points_.size() < (closed_ ? 4u : 2u)) {
    throw InputError(closed_ ? "a closed polyline needs at least three distinct points"
                             : "a polyline needs at least two distinct points");
  }
  cumulative_.push_back(0.0);
  for (std::size_t i = 1; i < points_.size(); ++i) {
    cumulative_.push_back(cumulative_.back() + distance(points_[i - 1], points_[i]));
  }
  // Menger curvature 4 area / (product of the sides) of each vertex and its neighbours.
  const std::size_t n = points_.size();
  vertex_curvature_.assign(n, 0.0);
  auto menger = [](const Point3& a, const Point3& b, const Point3& c) {
    const double sides = distance(a, b) * distance(b, c) * distance(c, a);
    return sides > 0 ? 2 * norm(cross(b - a, c - a)) / sides : 0.0;
  };
  for (std::size_t i = 1; i + 1 < n; ++i) {
    vertex_curvature_[i] = menger(points_[i - 1], points_[i], points_[i + 1]);
  }
  if (closed_) {
    vertex_curvature_[0] = vertex_curvature_[n - 1] =
        menger(points_[n - 2], points_[0], points_[1]);
  } else if (n > 2) {
    vertex_curvature_[0] = vertex_curvature_[1];
    vertex_curvature_[n - 1] = vertex_curvature_[n - 2];
  }
}

double PolylineCurve::curvature(double t) const {
  t = clamp(t);
  const std::size_t i = segment_of(t);
  const double f = (t - cumulative_[i]) / (cumulative_[i + 1] - cumulative_[i]);
  return (1 - f) * vertex_curvature_[i] + f * vertex_curvature_[i + 1];
}

double PolylineCurve::clamp(double t) const { return std::clamp(t, 0.0, cumulative_.back()); }

std::size_t PolylineCurve::segment_of(double t) const {
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), t);
  const std::size_t i =
      it == cumulative_.begin() ? 0 : static_cast<std::size_t>(it - cumulative_.begin()) - 1;
  return std::min(i, points_.size() - 2);
}

Point3 PolylineCurve::point(double t) const {
  t = clamp(t);
  const std::size_t i = segment_of(t);
  if (t == cumulative_[i]) return points_[i];
  if (t == cumulative_[i + 1]) return points_[i + 1];
  const double f = (t - cumulative_[i]) / (cumulative_[i + 1] - cumulative_[i]);
  return points_[i] + f * (points_[i + 1] - points_[i]);
}

double PolylineCurve::length(double ta, double tb) const { return clamp(tb) - clamp(ta); }

double PolylineCurve::parameter_at_length(double ta, double s) const {
  ta = clamp(ta);
  return s > 0 ? clamp(ta + s) : ta;
}

double PolylineCurve::closest(const Point3& p, double ta, double tb) const {
  ta = clamp(ta), tb = clamp(tb);
  if (!(ta < tb)) return ta;
  double best_t = ta, best_d = squared_norm(point(ta) - p);
  for (std::size_t i = segment_of(ta); i + 1 < points_.size() && cumulative_[i] < tb; ++i) {
    const double lo = std::max(ta, cumulative_[i]), hi = std::min(tb, cumulative_[i + 1]);
    const Point3 a = points_[i], d = points_[i + 1] - points_[i];
    const double len = cumulative_[i + 1] - cumulative_[i];
    const double t = std::clamp(cumulative_[i] + dot(p - a, d) / len, lo, hi);
    const double dist = squared_norm(point(t) - p);
    if (dist < best_d) best_d = dist, best_t = t;
  }
  return best_t;
}

std::vector<double> PolylineCurve::plane_crossings(const Point3& normal, double offset, double ta,
                                                   double tb) const {
  std::vector<double> out;
  ta = clamp(ta), tb = clamp(tb);
  if (!(ta < tb)) return out;
  auto h = [&](double t) { return dot(normal, point(t)) - offset; };
  // Walk the vertices inside (ta, tb) with ta and tb as extra ends.
  double a = ta, ha = h(ta);
  if (ha == 0) out.push_back(ta);
  for (std::size_t i = segment_of(ta) + 1; a < tb; ++i) {
    const double b = i < cumulative_.size() ? std::min(cumulative_[i], tb) : tb;
    const double hb = h(b);
    if (hb == 0 && ha != 0) {
      out.push_back(b);
    } else if ((ha < 0 && hb > 0) || (ha > 0 && hb < 0)) {
      out.push_back(std::clamp(a + (b - a) * ha / (ha - hb), a, b));
    }
    a = b, ha = hb;
  }
  return out;
}

}  // namespace rdmesh
