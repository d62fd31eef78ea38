// Surface evaluation and the Newton solvers of surface_evaluator.h.
#include "surface_evaluator.h"

#include <TColStd_Array1OfReal.hxx>
#include <algorithm>
#include <cmath>

#include "cad_model.h"

namespace rdmesh::cad {
namespace {

Point3 to_point(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
Point3 to_point(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }

double wrap(double x, double centre, double period) {
  return x - period * std::round((x - centre) / period);
}

std::vector<double> breaks(const GeomAdaptor_Surface& a, bool u) {
  const int n = u ? a.NbUIntervals(GeomAbs_CN) : a.NbVIntervals(GeomAbs_CN);
  std::vector<double> out;
  if (n < 1) return out;
  TColStd_Array1OfReal t(1, n + 1);
  if (u) {
    a.UIntervals(t, GeomAbs_CN);
  } else {
    a.VIntervals(t, GeomAbs_CN);
  }
  for (int i = 1; i <= n + 1; ++i) out.push_back(t(i));
  std::sort(out.begin(), out.end());
  return out;
}

bool near(const std::vector<double>& sorted, double x) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), x);
  auto close = [x](double k) { return std::fabs(x - k) <= 1e-10 * (1 + std::fabs(k)); };
  return (it != sorted.end() && close(*it)) || (it != sorted.begin() && close(*(it - 1)));
}

// Index of the span [k_i, k_i+1) holding x; the end spans extend outwards.
std::size_t span_index(const std::vector<double>& knots, double x) {
  const auto it = std::upper_bound(knots.begin() + 1, knots.end() - 1, x);
  return static_cast<std::size_t>(it - knots.begin()) - 1;
}

// Span caches beyond this many (u, v) spans: the adaptor's single cache instead.
constexpr std::size_t kMaxSpans = 1 << 16;

}  // namespace

SurfaceEvaluator::SurfaceEvaluator(const FacePatch& f) : surface_(f.surface), adaptor_(f.surface) {
  const GeomAbs_SurfaceType type = adaptor_.GetType();
  const bool extends = type == GeomAbs_BSplineSurface || type == GeomAbs_BezierSurface;
  const double mu = 0.25 * (f.u1 - f.u0), mv = 0.25 * (f.v1 - f.v0);
  u_lo_ = f.u0 - mu, u_hi_ = f.u1 + mu, v_lo_ = f.v0 - mv, v_hi_ = f.v1 + mv;
  if (!extends) {
    u_lo_ = std::max(u_lo_, adaptor_.FirstUParameter());
    u_hi_ = std::min(u_hi_, adaptor_.LastUParameter());
    v_lo_ = std::max(v_lo_, adaptor_.FirstVParameter());
    v_hi_ = std::min(v_hi_, adaptor_.LastVParameter());
  }
  if (adaptor_.IsUPeriodic()) u_period_ = adaptor_.UPeriod();
  if (adaptor_.IsVPeriodic()) v_period_ = adaptor_.VPeriod();
  u_mid_ = 0.5 * (f.u0 + f.u1), v_mid_ = 0.5 * (f.v0 + f.v1);
  if (type == GeomAbs_BSplineSurface) build_spans();
  if (bspline_) return;  // the span caches answer every (u, v): near_break() is never asked
  u_breaks_ = breaks(adaptor_, true);
  v_breaks_ = breaks(adaptor_, false);
  u_first_ = adaptor_.FirstUParameter(), v_first_ = adaptor_.FirstVParameter();
}

void SurfaceEvaluator::build_spans() {
  const Handle(Geom_BSplineSurface) b = adaptor_.BSpline();
  if (b.IsNull() || b->IsUPeriodic() || b->IsVPeriodic()) return;
  const std::size_t count =
      static_cast<std::size_t>(b->NbUKnots() - 1) * static_cast<std::size_t>(b->NbVKnots() - 1);
  if (count == 0 || count > kMaxSpans) return;
  Spans& s = bspline_.emplace();
  s.surface = b;
  s.u_flat.Resize(1, b->NbUPoles() + b->UDegree() + 1, false);
  s.v_flat.Resize(1, b->NbVPoles() + b->VDegree() + 1, false);
  b->UKnotSequence(s.u_flat);
  b->VKnotSequence(s.v_flat);
  s.poles.Resize(1, b->NbUPoles(), 1, b->NbVPoles(), false);
  b->Poles(s.poles);
  if (b->IsURational() || b->IsVRational()) {
    s.weights.emplace(1, b->NbUPoles(), 1, b->NbVPoles());
    b->Weights(*s.weights);
  }
  for (int i = 1; i <= b->NbUKnots(); ++i) s.u_knots.push_back(b->UKnot(i));
  for (int i = 1; i <= b->NbVKnots(); ++i) s.v_knots.push_back(b->VKnot(i));
  spans_.resize(count);
}

const BSplSLib_Cache& SurfaceEvaluator::span(double u, double v) const {
  const Spans& s = *bspline_;
  const std::size_t iu = span_index(s.u_knots, u), iv = span_index(s.v_knots, v);
  Handle(BSplSLib_Cache)& cache = spans_[iu * (s.v_knots.size() - 1) + iv];
  if (cache.IsNull()) {
    const TColStd_Array2OfReal* w = s.weights ? &*s.weights : nullptr;
    cache = new BSplSLib_Cache(s.surface->UDegree(), false, s.u_flat, s.surface->VDegree(), false,
                               s.v_flat, w);
    // Built at the span's centre: no doubt which span it is.
    cache->BuildCache(0.5 * (s.u_knots[iu] + s.u_knots[iu + 1]),
                      0.5 * (s.v_knots[iv] + s.v_knots[iv + 1]), s.u_flat, s.v_flat, s.poles, w);
  }
  return *cache;
}

std::vector<double> SurfaceEvaluator::interior_knots(bool u) const {
  if (!bspline_) return {};
  const std::vector<double>& k = u ? bspline_->u_knots : bspline_->v_knots;
  return {k.begin() + 1, k.end() - 1};
}

template <class F>
void SurfaceEvaluator::dispatch(double u, double v, F&& f) const {
  if (bspline_) {
    f(span(u, v));
  } else if (near_break(u, v)) {
    f(GeomAdaptor_Surface(surface_));
  } else {
    f(adaptor_);
  }
}

bool SurfaceEvaluator::near_break(double u, double v) const {
  if (u_period_ > 0) u -= u_period_ * std::floor((u - u_first_) / u_period_);
  if (v_period_ > 0) v -= v_period_ * std::floor((v - v_first_) / v_period_);
  return near(u_breaks_, u) || near(v_breaks_, v) ||
         (u_period_ > 0 && near(u_breaks_, u + u_period_)) ||
         (v_period_ > 0 && near(v_breaks_, v + v_period_));
}

void SurfaceEvaluator::d0(double u, double v, Point3& p) const {
  gp_Pnt q;
  dispatch(u, v, [&](const auto& source) { source.D0(u, v, q); });
  p = to_point(q);
}

void SurfaceEvaluator::d1(double u, double v, Point3& p, Point3& su, Point3& sv) const {
  gp_Pnt q;
  gp_Vec du, dv;
  dispatch(u, v, [&](const auto& source) { source.D1(u, v, q, du, dv); });
  p = to_point(q), su = to_point(du), sv = to_point(dv);
}

void SurfaceEvaluator::d2(double u, double v, Point3& p, Point3& su, Point3& sv, Point3& suu,
                          Point3& svv, Point3& suv) const {
  gp_Pnt q;
  gp_Vec du, dv, duu, dvv, duv;
  dispatch(u, v, [&](const auto& source) { source.D2(u, v, q, du, dv, duu, dvv, duv); });
  p = to_point(q), su = to_point(du), sv = to_point(dv);
  suu = to_point(duu), svv = to_point(dvv), suv = to_point(duv);
}

void SurfaceEvaluator::confine(double& u, double& v) const {
  u = u_period_ > 0 ? wrap(u, u_mid_, u_period_) : std::clamp(u, u_lo_, u_hi_);
  v = v_period_ > 0 ? wrap(v, v_mid_, v_period_) : std::clamp(v, v_lo_, v_hi_);
}

LineRoot newton_on_line(const SurfaceEvaluator& s, const Point3& a, const Point3& d, double u,
                        double v, double w, double tolerance) {
  constexpr int kIterations = 32, kHalvings = 12;
  LineRoot r;
  s.confine(u, v);
  Point3 p, su, sv;
  s.d1(u, v, p, su, sv);
  Point3 f = p - (a + w * d);
  double res = norm(f);
  const Point3 minus_d = -1.0 * d;
  for (int it = 0; it < kIterations && res > 0.01 * tolerance; ++it) {
    // Cramer's rule on [su sv -d] x = -f.
    const Point3 c23 = cross(sv, minus_d);
    const double det = dot(su, c23);
    const double scale = norm(su) * norm(sv);
    if (!(std::fabs(det) > 1e-14 * scale) || !std::isfinite(det)) break;
    const Point3 g = -1.0 * f;
    const double du = dot(g, c23) / det;
    const double dv = dot(su, cross(g, minus_d)) / det;
    const double dw = dot(su, cross(sv, g)) / det;
    bool improved = false;
    double lambda = 1;
    for (int h = 0; h < kHalvings; ++h, lambda *= 0.5) {
      double un = u + lambda * du, vn = v + lambda * dv;
      s.confine(un, vn);
      const double wn = w + lambda * dw;
      Point3 pn, sun, svn;
      s.d1(un, vn, pn, sun, svn);
      const Point3 fn = pn - (a + wn * d);
      const double rn = norm(fn);
      if (rn < res) {
        u = un, v = vn, w = wn, p = pn, su = sun, sv = svn, f = fn, res = rn;
        improved = true;
        break;
      }
    }
    if (!improved) break;
  }
  r.u = u, r.v = v, r.w = w, r.point = p, r.su = su, r.sv = sv, r.residual = res;
  r.converged = res <= tolerance;
  return r;
}

SurfaceFoot newton_foot(const SurfaceEvaluator& s, const Point3& x, double u, double v,
                        double tolerance) {
  constexpr int kIterations = 40, kHalvings = 12;
  SurfaceFoot foot;
  s.confine(u, v);
  Point3 p, su, sv, suu, svv, suv;
  s.d2(u, v, p, su, sv, suu, svv, suv);
  double dist2 = squared_norm(p - x);
  for (int it = 0; it < kIterations; ++it) {
    const Point3 e = p - x;
    const double gu = dot(e, su), gv = dot(e, sv);
    double huu = dot(su, su) + dot(e, suu), hvv = dot(sv, sv) + dot(e, svv);
    double huv = dot(su, sv) + dot(e, suv);
    if (!(huu > 0 && huu * hvv - huv * huv > 0)) {  // not convex here: Gauss-Newton
      huu = dot(su, su), hvv = dot(sv, sv), huv = dot(su, sv);
    }
    const double det = huu * hvv - huv * huv;
    if (!(det > 1e-300) || !std::isfinite(det)) break;
    const double du = -(hvv * gu - huv * gv) / det, dv = -(huu * gv - huv * gu) / det;
    bool improved = false;
    double lambda = 1, moved = 0;
    for (int h = 0; h < kHalvings; ++h, lambda *= 0.5) {
      double un = u + lambda * du, vn = v + lambda * dv;
      s.confine(un, vn);
      Point3 pn, sun, svn, suun, svvn, suvn;
      s.d2(un, vn, pn, sun, svn, suun, svvn, suvn);
      const double dn = squared_norm(pn - x);
      if (dn <= dist2) {
        moved = distance(pn, p);
        u = un, v = vn, p = pn, su = sun, sv = svn, suu = suun, svv = svvn, suv = suvn;
        dist2 = dn;
        improved = true;
        break;
      }
    }
    if (!improved) {
      // No descent along the Newton step: a foot when p - S has no tangential
      // part to speak of (measured as a length, against the tolerance).
      const double nu = norm(su), nv = norm(sv);
      foot.converged = nu > 0 && nv > 0 && std::fabs(dot(p - x, su)) <= 1e-3 * tolerance * nu &&
                       std::fabs(dot(p - x, sv)) <= 1e-3 * tolerance * nv;
      break;
    }
    if (moved <= 0.01 * tolerance) {
      foot.converged = true;
      break;
    }
  }
  foot.u = u, foot.v = v, foot.point = p;
  return foot;
}

}  // namespace rdmesh::cad
