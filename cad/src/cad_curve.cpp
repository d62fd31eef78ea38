// EdgeCurve: exact queries on an edge's 3D curve (Geom_Curve evaluation is
// const and cache-free, hence thread-safe; a B-spline's per-span polynomial
// caches are built up front and only read afterwards). Arc length is composite 5-point
// Gauss-Legendre over fixed cells with a cumulative table, so length() is
// additive by construction and parameter_at_length() inverts it by Newton.
#include <GeomLProp_CLProps.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Line.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <algorithm>
#include <cmath>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "cad_model.h"

namespace rdmesh::cad {
namespace {

constexpr double kNodes[5] = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                              0.9061798459386640};
constexpr double kWeights[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                0.2369268850561891, 0.2369268850561891};

Point3 to_point(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

}  // namespace

EdgeCurve::EdgeCurve(Handle(Geom_Curve) curve, double t0, double t1, Point3 q0, Point3 q1,
                     int samples)
    : curve_(std::move(curve)), t0_(t0), t1_(t1), samples_(std::max(samples, 4)) {
  Handle(Geom_Curve) basis = curve_;
  while (auto trimmed = Handle(Geom_TrimmedCurve)::DownCast(basis)) basis = trimmed->BasisCurve();
  build_span_caches(basis);
  straight_ = !Handle(Geom_Line)::DownCast(basis).IsNull();
  circle_ = Handle(Geom_Circle)::DownCast(basis);
  gp_Pnt c0, c1;  // the same evaluation as point()'s, so that point(t0) == q0
  evaluate(t0_, c0, nullptr, nullptr);
  evaluate(t1_, c1, nullptr, nullptr);
  d0_ = q0 - to_point(c0.XYZ());
  d1_ = q1 - to_point(c1.XYZ());
  const int cells = std::max(8, 2 * samples_);
  cell_ = (t1_ - t0_) / cells;
  cumulative_.assign(cells + 1, 0.0);
  for (int k = 0; k < cells; ++k) {
    cumulative_[k + 1] = cumulative_[k] + speed_integral(t0_ + k * cell_, t0_ + (k + 1) * cell_);
  }
  // The whole edge's length, asked by the loader (zero-length edges) and by
  // the protecting-ball planner: exactly what length(t0, t1) computed before.
  total_length_ = std::max(0.0, arc(t1_) - arc(t0_));
}

void EdgeCurve::build_span_caches(const Handle(Geom_Curve) & basis) {
  const Handle(Geom_BSplineCurve) b = Handle(Geom_BSplineCurve)::DownCast(basis);
  // A periodic curve's parameters may wrap past its knots: left to Geom_Curve.
  if (b.IsNull() || b->IsPeriodic()) return;
  const int degree = b->Degree();
  TColStd_Array1OfReal flat(1, b->NbPoles() + degree + 1);
  b->KnotSequence(flat);
  TColgp_Array1OfPnt poles(1, b->NbPoles());
  b->Poles(poles);
  TColStd_Array1OfReal weights(1, b->NbPoles());
  const bool rational = b->IsRational();
  if (rational) b->Weights(weights);
  const TColStd_Array1OfReal* w = rational ? &weights : nullptr;
  // The knots are distinct and increasing: the spans meeting [t0, t1] follow
  // one another without gaps.
  const double lo = std::min(t0_, t1_), hi = std::max(t0_, t1_);
  for (int k = 1; k < b->NbKnots(); ++k) {
    const double a = b->Knot(k), e = b->Knot(k + 1);
    if (e <= lo || a >= hi) continue;
    Handle(BSplCLib_Cache) cache = new BSplCLib_Cache(degree, false, flat, poles, w);
    cache->BuildCache(0.5 * (a + e), flat, poles, w);
    spans_.push_back(cache);
    span_start_.push_back(a);
    spans_end_ = e;
  }
}

void EdgeCurve::evaluate(double t, gp_Pnt& p, gp_Vec* d1, gp_Vec* d2) const {
  // BSplCLib_Cache and Geom_Curve name their evaluations alike.
  auto from = [&](const auto& source) {
    if (d2) {
      source.D2(t, p, *d1, *d2);
    } else if (d1) {
      source.D1(t, p, *d1);
    } else {
      source.D0(t, p);
    }
  };
  if (spans_.empty() || t < span_start_.front() || t > spans_end_) return from(*curve_);
  const auto it = std::upper_bound(span_start_.begin(), span_start_.end(), t);
  from(*spans_[std::max<std::ptrdiff_t>(it - span_start_.begin() - 1, 0)]);
}

Point3 EdgeCurve::point(double t) const {
  gp_Pnt p;
  evaluate(t, p, nullptr, nullptr);
  if (t == t0_) return to_point(p.XYZ()) + d0_;
  if (t == t1_) return to_point(p.XYZ()) + d1_;
  const double s = (t - t0_) / (t1_ - t0_);
  return to_point(p.XYZ()) + (1 - s) * d0_ + s * d1_;
}

double EdgeCurve::curvature(double t) const {
  GeomLProp_CLProps props(curve_, std::clamp(t, t0_, t1_), 2, 1e-12);
  return props.IsTangentDefined() ? props.Curvature() : 0.0;
}

Point3 EdgeCurve::derivative(double t) const {
  gp_Pnt p;
  gp_Vec v;
  evaluate(t, p, &v, nullptr);
  return to_point(v.XYZ()) + (1.0 / (t1_ - t0_)) * (d1_ - d0_);
}

double EdgeCurve::speed_integral(double u, double v) const {
  const double half = 0.5 * (v - u), mid = 0.5 * (u + v);
  double sum = 0;
  for (int i = 0; i < 5; ++i) sum += kWeights[i] * norm(derivative(mid + half * kNodes[i]));
  return half * sum;
}

double EdgeCurve::arc(double t) const {
  t = std::clamp(t, t0_, t1_);
  const int cells = static_cast<int>(cumulative_.size()) - 1;
  const int k = std::clamp(static_cast<int>((t - t0_) / cell_), 0, cells - 1);
  const double start = t0_ + k * cell_;
  return t <= start ? cumulative_[k] : cumulative_[k] + speed_integral(start, t);
}

double EdgeCurve::length(double ta, double tb) const {
  // arc() clamps to [t0, t1]: any range covering the edge has its whole length.
  if (ta <= t0_ && tb >= t1_) return total_length_;
  return std::max(0.0, arc(tb) - arc(ta));
}

double EdgeCurve::parameter_at_length(double ta, double s) const {
  const double target = arc(ta) + s;
  if (target >= cumulative_.back()) return t1_;
  if (s <= 0) return ta;
  // Bracket in the table, then safeguarded Newton on arc(t) - target from the
  // linear interpolation in the cell; done within 1e-12 of the curve's length.
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), target);
  const int k = std::clamp(static_cast<int>(it - cumulative_.begin()) - 1, 0,
                           static_cast<int>(cumulative_.size()) - 2);
  double lo = std::max(ta, t0_ + k * cell_), hi = std::min(t1_, t0_ + (k + 1) * cell_);
  const double in_cell = cumulative_[k + 1] - cumulative_[k];
  double t = in_cell > 0
                 ? t0_ + (k + std::clamp((target - cumulative_[k]) / in_cell, 0.0, 1.0)) * cell_
                 : 0.5 * (lo + hi);
  if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
  const double tolerance = 1e-12 * cumulative_.back();
  for (int it2 = 0; it2 < 60; ++it2) {
    const double f = arc(t) - target;
    if (std::fabs(f) <= tolerance) return t;
    if (f > 0)
      hi = t;
    else
      lo = t;
    const double speed = norm(derivative(t));
    double next = speed > 0 ? t - f / speed : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - t) <= 1e-15 * (t1_ - t0_) + 1e-300) return next;
    t = next;
  }
  return t;
}

int EdgeCurve::samples_over(double ta, double tb) const {
  const double fraction = (tb - ta) / (t1_ - t0_);
  return std::max(4, static_cast<int>(std::ceil(samples_ * fraction)));
}

double EdgeCurve::closest(const Point3& p, double ta, double tb) const {
  if (!(tb > ta)) return ta;
  if (straight_) {  // the foot of p on the chord, which is the curve
    const Point3 a = point(ta), ab = point(tb) - a;
    const double l2 = squared_norm(ab);
    if (l2 > 0) return ta + (tb - ta) * std::clamp(dot(p - a, ab) / l2, 0.0, 1.0);
  }
  if (!circle_.IsNull()) {
    // |C(t) - p| falls from the angle opposite p's to p's angle around the axis and
    // rises after it: p's angle when the arc holds it, else the nearer end.
    const gp_Ax2& ax = circle_->Position();
    const gp_Pnt& o = ax.Location();
    const Point3 q = p - Point3{o.X(), o.Y(), o.Z()};
    const gp_Dir &x = ax.XDirection(), &y = ax.YDirection();
    const double qx = q.x * x.X() + q.y * x.Y() + q.z * x.Z();
    const double qy = q.x * y.X() + q.y * y.Y() + q.z * y.Z();
    if (qx != 0 || qy != 0) {
      const double turn = 2 * M_PI;
      const double u = ta + std::fmod(std::fmod(std::atan2(qy, qx) - ta, turn) + turn, turn);
      if (u <= tb) return u;
      return squared_norm(point(ta) - p) <= squared_norm(point(tb) - p) ? ta : tb;
    }
  }
  const int n = samples_over(ta, tb);
  const double h = (tb - ta) / n;
  auto d2 = [&](double t) { return squared_norm(point(t) - p); };
  int best = 0;
  double best_d = d2(ta);
  for (int i = 1; i <= n; ++i) {
    const double d = d2(i == n ? tb : ta + i * h);
    if (d < best_d) best_d = d, best = i;
  }
  // Around the best sample, the root of f = (C(t) - p) . C'(t): safeguarded
  // Newton (f' = |C'|^2 + (C - p) . C''), bisecting when a step leaves the bracket.
  double lo = std::max(ta, ta + (best - 1) * h), hi = std::min(tb, ta + (best + 1) * h);
  const Point3 blend = (1.0 / (t1_ - t0_)) * (d1_ - d0_);
  auto f = [&](double t, double* slope) {
    gp_Pnt q;
    gp_Vec v1, v2;
    evaluate(t, q, &v1, &v2);
    const double s = (t - t0_) / (t1_ - t0_);
    const Point3 e = to_point(q.XYZ()) + (1 - s) * d0_ + s * d1_ - p;
    const Point3 c1 = to_point(v1.XYZ()) + blend;
    if (slope) *slope = dot(c1, c1) + dot(e, to_point(v2.XYZ()));
    return dot(e, c1);
  };
  double t = lo;
  const double flo = f(lo, nullptr), fhi = f(hi, nullptr);
  if (flo >= 0) {
    t = lo;  // distance growing from lo on
  } else if (fhi <= 0) {
    t = hi;  // still falling at hi
  } else {
    t = 0.5 * (lo + hi);
    for (int i = 0; i < 60 && hi - lo > 1e-15 * (t1_ - t0_); ++i) {
      double slope = 0;
      const double ft = f(t, &slope);
      if (ft == 0) break;
      (ft < 0 ? lo : hi) = t;
      double next = slope > 0 ? t - ft / slope : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      const bool done = std::fabs(next - t) <= 1e-15 * (t1_ - t0_);
      t = next;
      if (done) break;
    }
  }
  if (best_d < d2(t)) t = best == n ? tb : ta + best * h;
  return std::clamp(t, ta, tb);
}

std::vector<double> EdgeCurve::plane_crossings(const Point3& normal, double offset, double ta,
                                               double tb) const {
  std::vector<double> out;
  if (!(tb >= ta)) return out;
  if (straight_) {  // g is affine in t: one root, unless the segment lies in the plane
    const double ga = dot(normal, point(ta)) - offset, gb = dot(normal, point(tb)) - offset;
    if (ga == 0 && gb == 0) return {ta, tb};
    if (ga == 0) return {ta};
    if (gb == 0) return {tb};
    if ((ga < 0) != (gb < 0)) out.push_back(std::clamp(ta + (tb - ta) * ga / (ga - gb), ta, tb));
    return out;
  }
  const int n = samples_over(ta, tb);
  const double h = (tb - ta) / n;
  auto g = [&](double t) { return dot(normal, point(t)) - offset; };
  double prev_t = ta, prev = g(ta);
  if (prev == 0) out.push_back(ta);
  for (int i = 1; i <= n; ++i) {
    const double t = i == n ? tb : ta + i * h;
    const double cur = g(t);
    if (cur == 0) {
      out.push_back(t);
    } else if (prev != 0 && (prev < 0) != (cur < 0)) {
      // Illinois regula falsi, bisection fallback.
      double lo = prev_t, hi = t, flo = prev, fhi = cur;
      int side = 0;
      double x = 0.5 * (lo + hi);
      for (int it = 0; it < 100 && hi - lo > 1e-15 * (t1_ - t0_); ++it) {
        x = (lo * fhi - hi * flo) / (fhi - flo);
        if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
        const double fx = g(x);
        if (fx == 0) break;
        if ((fx < 0) == (flo < 0)) {
          lo = x, flo = fx;
          if (side == -1) fhi *= 0.5;
          side = -1;
        } else {
          hi = x, fhi = fx;
          if (side == 1) flo *= 0.5;
          side = 1;
        }
        x = std::fabs(flo) < std::fabs(fhi) ? lo : hi;
      }
      out.push_back(x);
    }
    prev_t = t, prev = cur;
  }
  return out;
}

}  // namespace rdmesh::cad
