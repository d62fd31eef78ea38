// ParametricCurve: adaptive sample table, arc length, inverse arc length,
// closest point and plane crossings (see rdmesh/parametric_curve.h).
#include "rdmesh/parametric_curve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "brent.h"
#include "rdmesh/errors.h"
#include "rdmesh/expression.h"

namespace rdmesh {

namespace {

constexpr int kMinIntervals = 64;
constexpr int kMaxDepth = 16;              // splits of one initial interval
constexpr double kMaxTurnCos = 0.9945;     // ~6 degrees between half-chords
constexpr double kMaxSagitta = 0.01;       // distance of the midpoint to the chord / chord
constexpr double kRelativeLength = 1e-13;  // Gauss-Legendre agreement per interval
constexpr double kRelativeParameter = 1e-14;

// 5-point Gauss-Legendre on [-1, 1].
constexpr double kNodes[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                              0.9061798459386640};
constexpr double kWeights[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                0.4786286704993665, 0.2369268850561891};

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

/// Distance of p to the line through a and b (to a when a == b).
double distance_to_line(Point3 p, Point3 a, Point3 b) {
  const Point3 d = b - a;
  const double dd = squared_norm(d);
  if (!(dd > 0)) return distance(p, a);
  return norm(cross(p - a, d)) / std::sqrt(dd);
}

ParametricCurve::Function expression_curve(const std::string& x, const std::string& y,
                                           const std::string& z) {
  auto compile = [](const std::string& text, const char* axis) {
    try {
      return Expression(text, {"t"});
    } catch (const InputError& e) {
      throw InputError(std::string(axis) + ": " + e.what());
    }
  };
  Expression ex = compile(x, "x"), ey = compile(y, "y"), ez = compile(z, "z");
  return [ex, ey, ez](double t) { return Point3{ex.at(t), ey.at(t), ez.at(t)}; };
}

}  // namespace

ParametricCurve::ParametricCurve(Function gamma, double t0, double t1)
    : gamma_(std::move(gamma)), t0_(t0), t1_(t1) {
  if (!gamma_) throw InputError("the curve function is empty");
  if (!std::isfinite(t0) || !std::isfinite(t1) || !(t0 < t1)) {
    throw InputError("the parameter range [" + number(t0) + ", " + number(t1) +
                     "] must be finite with t0 < t1");
  }
  build_table();
}

ParametricCurve::ParametricCurve(const std::string& x, const std::string& y, const std::string& z,
                                 double t0, double t1)
    : ParametricCurve(expression_curve(x, y, z), t0, t1) {}

void ParametricCurve::build_table() {
  // Recursive splitting of kMinIntervals uniform intervals; each accepted
  // interval records its end parameter and a bound on the arc-to-chord distance.
  auto eval = [this](double t) {
    const Point3 p = gamma_(t);
    if (!is_finite(p)) throw InputError("the curve is not finite at t = " + number(t));
    return p;
  };
  auto split = [&](auto&& self, double a, Point3 pa, double b, Point3 pb, int depth) -> void {
    const double m = 0.5 * (a + b);
    const Point3 pm = eval(m);
    const Point3 c1 = pm - pa, c2 = pb - pm;
    const double l1 = norm(c1), l2 = norm(c2), chord = distance(pa, pb);
    const bool turning = l1 > 0 && l2 > 0 && dot(c1, c2) < kMaxTurnCos * l1 * l2;
    const bool bulging = distance_to_line(pm, pa, pb) > kMaxSagitta * chord;
    if ((turning || bulging) && depth < kMaxDepth && m > a && m < b) {
      self(self, a, pa, m, pm, depth + 1);
      self(self, m, pm, b, pb, depth + 1);
      return;
    }
    double dev = distance_to_line(pm, pa, pb);
    for (double f : {0.25, 0.75})
      dev = std::max(dev, distance_to_line(eval(a + f * (b - a)), pa, pb));
    params_.push_back(b);
    deviation_.push_back(2 * dev);
  };
  params_.push_back(t0_);
  Point3 prev = eval(t0_);
  const Point3 first = prev;
  Box3 extent = Box3::around({first});
  for (int i = 1; i <= kMinIntervals; ++i) {
    const double a = params_.back();
    const double b = i == kMinIntervals ? t1_ : t0_ + (t1_ - t0_) * i / kMinIntervals;
    const Point3 pb = eval(b);
    split(split, a, prev, b, pb, 0);
    prev = pb;
  }
  for (double t : params_) extent.grow(gamma_(t));
  // Rounding floor of a finite-difference length integral over one interval.
  noise_ =
      1e3 * std::numeric_limits<double>::epsilon() * std::max(norm(extent.lo), norm(extent.hi));
  cumulative_.assign(1, 0.0);
  for (std::size_t i = 0; i + 1 < params_.size(); ++i) {
    const double whole = distance(gamma_(params_[i]), gamma_(params_[i + 1]));
    cumulative_.push_back(cumulative_.back() + integrate(params_[i], params_[i + 1], whole, 0));
  }
  if (!std::isfinite(total_length())) {
    double largest = 0;
    for (const Point3& c : {extent.lo, extent.hi})
      largest = std::max({largest, std::fabs(c.x), std::fabs(c.y), std::fabs(c.z)});
    throw InputError("its arc length is not finite: coordinates up to " + number(largest) +
                     " overflow its derivative");
  }
  closed_ = distance(first, prev) <= 1e-10 * std::max(extent.diagonal(), total_length());
}

Point3 ParametricCurve::point(double t) const { return gamma_(clamp(t)); }

std::size_t ParametricCurve::interval_of(double t) const {
  const auto it = std::upper_bound(params_.begin(), params_.end(), t);
  const std::size_t i =
      it == params_.begin() ? 0 : static_cast<std::size_t>(it - params_.begin()) - 1;
  return std::min(i, params_.size() - 2);
}

Point3 ParametricCurve::derivative(double t) const {
  t = clamp(t);
  const std::size_t i = interval_of(t);
  const double h = 0.01 * (params_[i + 1] - params_[i]);
  auto f = [this](double s) { return gamma_(s); };
  if (t - 2 * h < t0_ || t + 2 * h > t1_) {
    const double s = t - 2 * h < t0_ ? h : -h;  // one-sided, towards the inside
    const Point3 d = -25.0 * f(t) + 48.0 * f(t + s) + -36.0 * f(t + 2 * s) + 16.0 * f(t + 3 * s) +
                     -3.0 * f(t + 4 * s);
    return (1 / (12 * s)) * d;
  }
  const Point3 d = f(t - 2 * h) + -8.0 * f(t - h) + 8.0 * f(t + h) + -1.0 * f(t + 2 * h);
  return (1 / (12 * h)) * d;
}

double ParametricCurve::curvature(double t) const {
  t = clamp(t);
  const std::size_t i = interval_of(t);
  const double h = 0.01 * (params_[i + 1] - params_[i]);
  Point3 second;
  if (t - 2 * h < t0_ || t + 2 * h > t1_) {
    const double s = t - 2 * h < t0_ ? h : -h;  // one-sided, towards the inside
    second = (1 / (s * s)) * (2.0 * gamma_(t) + -5.0 * gamma_(t + s) + 4.0 * gamma_(t + 2 * s) +
                              -1.0 * gamma_(t + 3 * s));
  } else {
    second =
        (1 / (12 * h * h)) * (-1.0 * gamma_(t - 2 * h) + 16.0 * gamma_(t - h) + -30.0 * gamma_(t) +
                              16.0 * gamma_(t + h) + -1.0 * gamma_(t + 2 * h));
  }
  const Point3 first = derivative(t);
  const double speed = norm(first);
  if (!(speed > 0)) return 0;
  return norm(cross(first, second)) / (speed * speed * speed);
}

double ParametricCurve::integrate(double a, double b, double whole, int depth) const {
  auto gauss = [this](double lo, double hi) {
    const double c = 0.5 * (lo + hi), r = 0.5 * (hi - lo);
    double sum = 0;
    for (int k = 0; k < 5; ++k) sum += kWeights[k] * speed(c + r * kNodes[k]);
    return r * sum;
  };
  const double m = 0.5 * (a + b);
  const double one = gauss(a, b), two = gauss(a, m) + gauss(m, b);
  const double tol = std::max(kRelativeLength * std::max(whole, std::fabs(two)), noise_);
  // A speed that overflows (coordinates near the largest double, whose finite
  // differences do) never agrees: splitting it would only cost 4096 times more.
  if (!std::isfinite(two) || std::fabs(one - two) <= tol || depth >= 12) {
    return two;
  }
  return integrate(a, m, whole, depth + 1) + integrate(m, b, whole, depth + 1);
}

double ParametricCurve::cumulative_at(double t) const {
  t = clamp(t);
  const std::size_t i = interval_of(t);
  if (t == params_[i]) return cumulative_[i];
  const double whole = cumulative_[i + 1] - cumulative_[i];
  return cumulative_[i] + integrate(params_[i], t, whole, 0);
}

double ParametricCurve::length(double ta, double tb) const {
  ta = clamp(ta), tb = clamp(tb);
  if (ta > tb) return -length(tb, ta);
  const std::size_t i = interval_of(ta);
  if (i == interval_of(tb) && ta < tb) {
    return integrate(ta, tb, cumulative_[i + 1] - cumulative_[i], 0);
  }
  return cumulative_at(tb) - cumulative_at(ta);
}

double ParametricCurve::parameter_at_length(double ta, double s) const {
  ta = clamp(ta);
  if (!(s > 0)) return ta;
  const double target = cumulative_at(ta) + s;
  if (target >= total_length()) return t1_;
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), target);
  const std::size_t i = static_cast<std::size_t>(it - cumulative_.begin()) - 1;
  double lo = std::max(params_[i], ta), hi = params_[i + 1];
  const double base = lo == params_[i] ? cumulative_[i] : cumulative_at(lo);
  const double whole = cumulative_[i + 1] - cumulative_[i];
  const double xtol = kRelativeParameter * (t1_ - t0_);
  // F(t) = length(lo_start, t) - (target - base), increasing.
  const double start = lo, goal = target - base;
  double t =
      lo + (hi - lo) * std::clamp(goal / std::max(cumulative_[i + 1] - base, 1e-300), 0.0, 1.0);
  for (int it_count = 0; it_count < 100; ++it_count) {
    const double f = (t > start ? integrate(start, t, whole, 0) : 0.0) - goal;
    if (f == 0) return t;
    if (f < 0)
      lo = t;
    else
      hi = t;
    const double v = speed(t);
    double next = v > 0 ? t - f / v : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - t) <= xtol || hi - lo <= xtol) return next;
    t = next;
  }
  return t;
}

void ParametricCurve::samples_between(double ta, double tb, std::vector<double>& out) const {
  out.clear();
  out.push_back(ta);
  const auto first = std::upper_bound(params_.begin(), params_.end(), ta);
  for (auto it = first; it != params_.end() && *it < tb; ++it) out.push_back(*it);
  out.push_back(tb);
  if (out.size() < 17) {  // refine a short range uniformly
    out.clear();
    for (int k = 0; k <= 16; ++k) out.push_back(k == 16 ? tb : ta + (tb - ta) * k / 16);
  }
}

double ParametricCurve::closest(const Point3& p, double ta, double tb) const {
  ta = clamp(ta), tb = clamp(tb);
  if (!(ta < tb)) return ta;
  std::vector<double> ts;
  samples_between(ta, tb, ts);
  std::vector<double> d(ts.size());
  for (std::size_t k = 0; k < ts.size(); ++k) d[k] = squared_norm(gamma_(ts[k]) - p);
  auto g = [&](double t) { return dot(gamma_(t) - p, derivative(t)); };
  const double xtol = kRelativeParameter * (t1_ - t0_);
  double best_t = d.front() <= d.back() ? ta : tb;
  double best_d = std::min(d.front(), d.back());
  for (std::size_t k = 0; k < ts.size(); ++k) {
    const bool local_min = (k == 0 || d[k] <= d[k - 1]) && (k + 1 == ts.size() || d[k] <= d[k + 1]);
    if (!local_min) continue;
    // Look for the minimum in the two neighbouring intervals.
    for (std::size_t lo = k == 0 ? 0 : k - 1; lo <= k && lo + 1 < ts.size(); ++lo) {
      const double a = ts[lo], b = ts[lo + 1];
      const double ga = g(a), gb = g(b);
      if (!(ga < 0 && gb >= 0)) continue;
      const detail::Transition tr = detail::brent_transition(g, a, ga, b, gb, xtol);
      const double dt = squared_norm(gamma_(tr.best) - p);
      if (dt < best_d) best_d = dt, best_t = tr.best;
    }
    if (d[k] < best_d) best_d = d[k], best_t = ts[k];
  }
  return best_t;
}

std::vector<double> ParametricCurve::plane_crossings(const Point3& normal, double offset, double ta,
                                                     double tb) const {
  std::vector<double> out;
  ta = clamp(ta), tb = clamp(tb);
  if (!(ta < tb)) return out;
  const double nn = norm(normal);
  auto h = [&](double t) { return dot(normal, gamma_(t)) - offset; };
  const double xtol = kRelativeParameter * (t1_ - t0_);
  const double min_width = 1e-12 * (t1_ - t0_);
  // Depth-first over [a, b] (inside table interval i): a crossing needs a sign
  // change, or |h| at the ends small enough for the arc's bulge to reach the plane.
  auto search = [&](auto&& self, double a, double ha, double b, double hb, double bound) -> void {
    if ((ha < 0) != (hb < 0)) {
      out.push_back(detail::brent_transition(h, a, ha, b, hb, xtol).best);
      return;
    }
    if (std::min(std::fabs(ha), std::fabs(hb)) > bound * nn || b - a <= min_width) return;
    const double m = 0.5 * (a + b), hm = h(m);
    self(self, a, ha, m, hm, 0.25 * bound);
    self(self, m, hm, b, hb, 0.25 * bound);
  };
  std::vector<double> ts;
  samples_between(ta, tb, ts);
  double prev = h(ts[0]);
  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    const double hb = h(ts[k + 1]);
    const std::size_t i = interval_of(0.5 * (ts[k] + ts[k + 1]));
    const double scale = std::min(1.0, (ts[k + 1] - ts[k]) / (params_[i + 1] - params_[i]));
    search(search, ts[k], prev, ts[k + 1], hb, deviation_[i] * scale * scale);
    prev = hb;
  }
  std::sort(out.begin(), out.end());
  const double merge = 1e-12 * (t1_ - t0_);
  out.erase(
      std::unique(out.begin(), out.end(), [merge](double a, double b) { return b - a <= merge; }),
      out.end());
  return out;
}

}  // namespace rdmesh
