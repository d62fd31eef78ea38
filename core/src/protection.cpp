// Protecting balls on corners and curves (see protection.h for the
// properties B1-B3, the construction and why they make refinement end near
// small angles).
#include "protection.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>

#include "rdmesh/errors.h"
#include "rdmesh/feature_name.h"
#include "rdmesh/mesher.h"
#include "simplex_geometry.h"

namespace rdmesh::detail {

/// A ball of the plan, for the separation test.
struct PlanBall {
  Point3 center;
  double radius;
  BallRef ref;
  bool moved;  ///< since the last separation pass
};

namespace {

/// A fixed pseudo-random number in [-1, 1] for sample k of curve j.
double jitter(std::size_t j, std::size_t k) {
  std::uint64_t x = (static_cast<std::uint64_t>(j) << 32) ^ k ^ 0x9e3779b97f4a7c15ULL;
  x ^= x >> 33;
  x *= 0xff51afd7ed558ccdULL;
  x ^= x >> 33;
  x *= 0xc4ceb9fe1a85ec53ULL;
  x ^= x >> 33;
  return static_cast<double>(x >> 11) / static_cast<double>(1ULL << 52) - 1.0;
}

/// A hierarchical hash grid of the plan's balls for the B2 test: a ball lives
/// at the level whose cells are at least its reach's diameter, by its centre
/// only. Each ball is tested against the balls of its own level and of the
/// coarser ones in the cells near it, so every pair is seen once, from its
/// smaller ball.
///
/// Two grids: every ball, and the balls that moved. A moved ball looks for
/// partners among all, an unmoved one among the moved only: each pair with a
/// moved ball is still seen once (from its smaller ball, or from its first one
/// at the same level), a pair of unmoved balls is not looked at. Per level,
/// (cell key, ball) pairs sorted: one allocation per level, and a cell's balls
/// in ball order.
class BallGrid {
 public:
  explicit BallGrid(const std::vector<PlanBall>& balls) : balls_(balls), level_(balls.size()) {
    constexpr double kGap = ProtectionPlanner::kGap;
    double smallest = std::numeric_limits<double>::infinity();
    for (const PlanBall& b : balls) smallest = std::min(smallest, b.radius);
    base_ = std::max(2 * (1 + kGap) * smallest, 1e-300);
    for (std::size_t k = 0; k < balls.size(); ++k) {
      level_[k] = std::max(
          0, static_cast<int>(std::ceil(std::log2(2 * (1 + kGap) * balls[k].radius / base_))));
      const double cell = std::ldexp(base_, level_[k]);
      const Point3& c = balls[k].center;
      const std::uint64_t where = key(static_cast<std::int64_t>(std::floor(c.x / cell)),
                                      static_cast<std::int64_t>(std::floor(c.y / cell)),
                                      static_cast<std::int64_t>(std::floor(c.z / cell)));
      all_[level_[k]].emplace_back(where, static_cast<int>(k));
      if (balls[k].moved) moved_[level_[k]].emplace_back(where, static_cast<int>(k));
    }
    for (Grid* grid : {&all_, &moved_}) {
      for (auto& [lvl, cells] : *grid) std::sort(cells.begin(), cells.end());
    }
  }

  /// Calls visit(other) for every ball `other` that ball k is tested against,
  /// in a fixed order.
  template <class Visit>
  void for_each_partner(std::size_t k, Visit&& visit) const {
    const PlanBall& b = balls_[k];
    const Grid& grids = b.moved ? all_ : moved_;
    for (auto g = grids.lower_bound(level_[k]); g != grids.end(); ++g) {
      const double cell = std::ldexp(base_, g->first);
      const double reach = (1 + ProtectionPlanner::kGap) * b.radius + 0.5 * cell;
      const double c[3] = {b.center.x, b.center.y, b.center.z};
      std::int64_t lo[3], hi[3];
      for (int axis = 0; axis < 3; ++axis) {
        lo[axis] = static_cast<std::int64_t>(std::floor((c[axis] - reach) / cell));
        hi[axis] = static_cast<std::int64_t>(std::floor((c[axis] + reach) / cell));
      }
      for (std::int64_t x = lo[0]; x <= hi[0]; ++x) {
        for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
          for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
            visit_cell(k, g->second, key(x, y, z), visit);
          }
        }
      }
    }
  }

 private:
  using Cells = std::vector<std::pair<std::uint64_t, int>>;
  using Grid = std::map<int, Cells>;

  static std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z) {
    return (static_cast<std::uint64_t>(x & 0x1fffff) << 42) |
           (static_cast<std::uint64_t>(y & 0x1fffff) << 21) |
           static_cast<std::uint64_t>(z & 0x1fffff);
  }

  template <class Visit>
  void visit_cell(std::size_t k, const Cells& cells, std::uint64_t where, Visit& visit) const {
    auto here = std::lower_bound(cells.begin(), cells.end(),
                                 std::make_pair(where, std::numeric_limits<int>::min()));
    for (; here != cells.end() && here->first == where; ++here) {
      const int other = here->second;
      // Same level: each pair once, from its first ball.
      if (level_[other] == level_[k] && other <= static_cast<int>(k)) continue;
      visit(static_cast<std::size_t>(other));
    }
  }

  const std::vector<PlanBall>& balls_;
  double base_ = 0;
  std::vector<int> level_;
  Grid all_, moved_;
};

}  // namespace

ProtectionPlanner::ProtectionPlanner(std::vector<ProtectedCurve> curves,
                                     std::vector<CornerInfo> corners, const Criteria& criteria,
                                     double min_size, const DomainOracle* oracle)
    : corners_(std::move(corners)), criteria_(criteria), min_size_(min_size), oracle_(oracle) {
  corner_clear_.assign(corners_.size(), 0);
  corner_moved_.assign(corners_.size(), 1);
  // A corner's ball: within the edge size, and well clear of the other corners.
  corner_radius_.resize(corners_.size());
  for (std::size_t q = 0; q < corners_.size(); ++q) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t o = 0; o < corners_.size(); ++o) {
      if (o != q) nearest = std::min(nearest, distance(corners_[q].point, corners_[o].point));
    }
    corner_radius_[q] =
        std::max(min_size_, std::min(criteria_.edge_size(corners_[q].point), 0.4 * nearest));
  }
  for (ProtectedCurve& c : curves) {
    CurveData d;
    d.length = c.curve->length(c.info.t_begin, c.info.t_end);
    if (!c.info.closed) {
      const int n = static_cast<int>(corners_.size());
      d.start = c.info.start.value - 1;
      d.end = c.info.end.value - 1;
      if (d.start < 0 || d.start >= n || d.end < 0 || d.end >= n) {
        throw OracleError(feature_name(c.info.id, c.info.name) + " ends at no listed corner");
      }
    }
    if (!(d.length > 0) || !std::isfinite(d.length)) {
      throw OracleError(feature_name(c.info.id, c.info.name) + " has no positive finite length");
    }
    d.c = std::move(c);
    curves_.push_back(std::move(d));
  }
}

double ProtectionPlanner::step_at(const CurveData& d, double a) const {
  auto size_at = [&](double x) {
    if (criteria_.edge_size.is_uniform()) return 2 * criteria_.edge_size.constant;
    const double t = d.c.curve->parameter_at_length(d.c.info.t_begin, std::min(x, d.length));
    return 2 * criteria_.edge_size(d.c.curve->point(t));
  };
  // The step s from a must respect every constraint seen from its window
  // [a, a + s], its far end included (the next sample's own cap). The corner
  // balls at the ends act as caps: sizes grow from them gradually (a first
  // sample much larger than its corner's ball would swallow it).
  const double cap_start = d.start >= 0 ? corner_radius_[d.start] / kRadiusRatio : HUGE_VAL;
  const double cap_end = d.end >= 0 ? corner_radius_[d.end] / kRadiusRatio : HUGE_VAL;
  const double size_here = size_at(a);
  // A cap (value v) `ahead` of a allows the steps s with s <= v + kGrowth * gap,
  // gap = max(0, ahead - s) the part of the way to it the window leaves out:
  // an interval [0, s*] with s* = v when the window may reach it (v > ahead),
  // else the s at which the step meets the grown cap.
  auto allowed = [](double v, double ahead) {
    return v > ahead ? v : (v + kGrowth * ahead) / (1 + kGrowth);
  };
  double s = std::min(size_here, cap_start + kGrowth * a);
  if (d.end >= 0) s = std::min(s, allowed(cap_end, std::max(0.0, d.length - a)));
  // A cap at (circular) distance c allows at least kGrowth c / (1 + kGrowth):
  // beyond `reach` (twice that, for rounding) none can lower s.
  const double reach = 2 * s * (1 + kGrowth) / kGrowth;
  d.caps.for_each_near(a, reach, d.c.info.closed, d.length, [&](const SizeCaps::Cap& cap) {
    s = std::min(
        s, cap.arc < a ? cap.value + kGrowth * (a - cap.arc) : allowed(cap.value, cap.arc - a));
    if (d.c.info.closed) {  // the cap seen around the curve's closing point
      const double wrapped =
          std::min(std::fabs(cap.arc + d.length - a), std::fabs(cap.arc - d.length - a));
      s = std::min(s, allowed(cap.value, wrapped));
    }
  });
  if (!criteria_.edge_size.is_uniform()) {
    // The size at the window's far end depends on s in no monotone way: the
    // largest s (at most the caps' s*) that it allows, by bisection.
    double lo = 0, hi = s;
    if (size_at(a + hi) < hi) {
      for (int it = 0; it < 40 && hi - lo > 1e-6 * hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        (mid <= size_at(a + mid) ? lo : hi) = mid;
      }
      s = lo;
    }
  }
  return std::max(s, 2 * min_size_);
}

double ProtectionPlanner::exit_arc(const CurveData& d, const Point3& q, double r,
                                   bool from_end) const {
  const Curve& curve = *d.c.curve;
  const CurveInfo& info = d.c.info;
  auto param = [&](double a) {
    return curve.parameter_at_length(info.t_begin, from_end ? d.length - a : a);
  };
  auto gap = [&](double t) { return distance(curve.point(t), q) - r; };
  // Arc length >= chord: the curve leaves the ball at arc length >= r.
  double lo = 0, hi = std::min(r, d.length);
  double t_lo = from_end ? info.t_end : info.t_begin, t_hi = param(hi);
  while (gap(t_hi) < 0) {
    if (hi >= d.length) return d.length;  // the ball holds the whole curve
    lo = hi, t_lo = t_hi;
    hi = std::min(d.length, 1.5 * hi + r);
    t_hi = param(hi);
  }
  // Bisection on the parameter (the arc is monotone in it): a point per step
  // instead of an arc-length inversion; the arc is measured once at the end.
  for (int it = 0; it < 50 && std::fabs(t_hi - t_lo) > 1e-13 * (info.t_end - info.t_begin); ++it) {
    const double mid = 0.5 * (t_lo + t_hi);
    (gap(mid) < 0 ? t_lo : t_hi) = mid;
  }
  const double a = from_end ? curve.length(t_hi, info.t_end) : curve.length(info.t_begin, t_hi);
  return std::clamp(a, lo, hi);
}

void ProtectionPlanner::sample_curve(CurveData& d) {
  const Curve& curve = *d.c.curve;
  const CurveInfo& info = d.c.info;
  auto sample = [&](double a, double radius) {
    const double t = curve.parameter_at_length(info.t_begin, a);
    return BallSample{t, a, curve.point(t), radius};
  };
  d.samples.clear();
  d.clear = false;
  d.moved = true;
  double a0 = 0, a1 = d.length;
  if (!info.closed) {
    const Point3 qs = corners_[d.start].point, qe = corners_[d.end].point;
    d.samples.push_back({info.t_begin, 0, qs, corner_radius_[d.start]});
    a0 = exit_arc(d, qs, corner_radius_[d.start], false);
    a1 = d.length - exit_arc(d, qe, corner_radius_[d.end], true);
  }
  const double span = a1 - a0;
  const double step0 = step_at(d, a0);
  if (!info.closed && span <= kRadiusRatio * 1.2 * step0) {
    // The corner balls (nearly) meet: one sample between them.
    const double mid = std::clamp(0.5 * (a0 + a1), 0.0, d.length);
    d.samples.push_back(sample(mid, kRadiusRatio * std::min(step0, step_at(d, mid))));
  } else {
    // March with the local step until a1 is passed, then shorten the last
    // steps in proportion so that the last sample lands exactly on a1. Steps
    // only ever shrink (a longer step could exceed the cap it was measured
    // against), and every other sample keeps the position its caps were
    // measured at (a uniform rescaling would shift a long curve's far samples).
    std::vector<double> arcs{a0}, steps;
    while (arcs.back() < a1) {
      deadline_.check(1024);
      // Shortened so that the jittered chords below stay within the step.
      steps.push_back(step_at(d, arcs.back()) / (1 + 2 * kJitter));
      arcs.push_back(arcs.back() + steps.back());
    }
    const std::size_t min_steps = info.closed ? 3 : 1;
    if (steps.size() < min_steps) {  // too short a closed curve: equal thirds
      steps.assign(min_steps, span / min_steps);
      arcs.assign(1, a0);
      for (double s : steps) arcs.push_back(arcs.back() + s);
    }
    const std::size_t n = steps.size();
    // As few trailing steps as keep each at >= 3/4 of its length (all if need be).
    const double overshoot = arcs[n] - a1;
    std::size_t m = 1;
    double tail = steps[n - 1];
    while (m < n && overshoot > 0.25 * tail) tail += steps[n - ++m];
    const double shrink = (tail - overshoot) / tail;
    for (std::size_t k = n - m; k < n; ++k) {
      steps[k] *= shrink;
      arcs[k + 1] = arcs[k] + steps[k];
    }
    arcs[n] = a1;
    for (std::size_t k = 0; k <= n; ++k) {
      if (info.closed && k == n) break;  // the first sample again, added below
      double s = k < n ? steps[k] : steps[n - 1];
      if (k > 0) s = std::max(s, steps[k - 1]);
      if (info.closed && k == 0) s = std::max(s, steps[n - 1]);
      // Inner samples move by a fixed pseudo-random kJitter of their step:
      // symmetric features sampled alike (two meridians at the same heights)
      // would give co-spherical ball quadruples, flat cells whose orthocenter
      // is undefined. The margins of B1 and B2 absorb the move.
      double a = arcs[k];
      if (k > 0 && k < n)
        a += kJitter * std::min(steps[k - 1], steps[k]) * jitter(curve_index(d), k);
      d.samples.push_back(sample(a, kRadiusRatio * s));
    }
    if (info.closed) {
      BallSample last = d.samples.front();
      last.t = info.t_end;
      last.arc = d.length;
      d.samples.push_back(last);
    }
  }
  if (!info.closed) {
    d.samples.push_back({info.t_end, d.length, corners_[d.end].point, corner_radius_[d.end]});
  }
}

bool ProtectionPlanner::shrink_ball(const BallRef& b, double factor, bool below_caps) {
  if (b.is_corner()) {
    const int q = b.corner();
    double& r = corner_radius_[q];
    if (factor * r < min_size_) return false;
    r *= factor;
    corner_clear_[q] = 0;
    corner_moved_[q] = 1;
    for (CurveData& d : curves_) d.dirty = d.dirty || d.start == q || d.end == q;
    return true;
  }
  CurveData& d = curves_[b.curve()];
  const BallSample& s = d.samples[b.sample()];
  // A cap lower than the caps there now, never below the floor; false when it
  // would change nothing (the ball is as small as it may get). A sample's ball
  // follows the longer of its two steps, so it may exceed the caps at its own
  // place: with below_caps the new cap is a fraction of those.
  const double now = d.caps.lowest_at(s.arc, kGrowth);
  const double size = s.radius / kRadiusRatio;
  const double value = std::max(factor * (below_caps ? std::min(now, size) : size), 2 * min_size_);
  if (value >= 0.999 * std::min(now, size)) return false;
  d.dirty = true;
  d.caps.add(s.arc, value);
  return true;
}

void ProtectionPlanner::clamp_radius(const BallRef& b, double radius) {
  if (!b.is_corner()) {
    CurveData& d = curves_[b.curve()];
    BallSample& s = d.samples[b.sample()];
    s.radius = std::min(s.radius, radius);
    if (d.c.info.closed && b.sample() == 0) d.samples.back().radius = s.radius;
    return;
  }
  const int q = b.corner();
  double& r = corner_radius_[q];
  r = std::min(r, radius);
  corner_moved_[q] = 1;
  for (CurveData& d : curves_) {  // the corner's copies at curve ends
    if (d.start == q) d.samples.front().radius = r;
    if (d.end == q) d.samples.back().radius = r;
  }
}

double ProtectionPlanner::radius_of(const BallRef& b) const {
  return b.is_corner() ? corner_radius_[b.corner()] : curves_[b.curve()].samples[b.sample()].radius;
}

bool ProtectionPlanner::check_arcs() {
  bool changed = false;
  for (std::size_t j = 0; j < curves_.size(); ++j) {
    const CurveData& d = curves_[j];
    const std::vector<BallSample>& s = d.samples;
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
      const Point3 mid = d.c.curve->point(0.5 * (s[i].t + s[i + 1].t));
      const double sigma = criteria_.edge_size(mid);
      const double dmax = criteria_.facet_distance(mid), dmax2 = dmax * dmax;
      const bool long_chord = distance(s[i].point, s[i + 1].point) > 2 * sigma;
      if (!long_chord && squared_distance_to_segment(mid, s[i].point, s[i + 1].point) <= dmax2) {
        continue;
      }
      // Shrink both ends (a corner end is the corner's ball).
      for (std::size_t k : {i, i + 1}) {
        // A closed curve's last sample repeats its first.
        BallRef ref = BallRef::on_curve(j, d.c.info.closed && k + 1 == s.size() ? 0 : k);
        if (!d.c.info.closed && k == 0) ref = BallRef::at_corner(d.start);
        if (!d.c.info.closed && k + 1 == s.size()) ref = BallRef::at_corner(d.end);
        changed = shrink_ball(ref, 0.7) || changed;
      }
    }
  }
  return changed;
}

std::vector<int> ProtectionPlanner::curves_touching(const BallRef& ball) const {
  std::vector<int> corners;
  std::vector<int> out;
  if (ball.is_corner()) {
    corners.push_back(ball.corner());
  } else {
    out.push_back(ball.curve());
    const CurveData& d = curves_[static_cast<std::size_t>(ball.curve())];
    const int last = static_cast<int>(d.samples.size()) - 1;
    if (!d.c.info.closed && ball.sample() <= 1) corners.push_back(d.start);
    if (!d.c.info.closed && ball.sample() >= last - 1) corners.push_back(d.end);
  }
  for (std::size_t j = 0; j < curves_.size(); ++j) {
    const bool at_corner = std::find_if(corners.begin(), corners.end(), [&](int c) {
                             return c >= 0 && (curves_[j].start == c || curves_[j].end == c);
                           }) != corners.end();
    const bool own = !ball.is_corner() && static_cast<int>(j) == ball.curve();
    if (at_corner && !own) out.push_back(static_cast<int>(j));
  }
  return out;
}

std::string ProtectionPlanner::name(const BallRef& b) const {
  if (b.is_corner()) return feature_name(CornerId{b.corner() + 1});
  const CurveInfo& info = curves_[b.curve()].c.info;
  return feature_name(info.id, info.name);
}

double ProtectionPlanner::feature_distance(const BallRef& b, const Point3& x) const {
  if (b.is_corner()) return distance(x, corners_[b.corner()].point);
  const CurveData& d = curves_[b.curve()];
  const std::vector<BallSample>& s = d.samples;
  const int last = static_cast<int>(s.size()) - 1;
  auto arc = [&](int i, int j) {
    return distance(x, d.c.curve->point(d.c.curve->closest(x, s[i].t, s[j].t)));
  };
  const int i = b.sample();
  double best = arc(std::max(0, i - 1), std::min(last, i + 1));
  // A closed curve's first sample is also its last: the arc before it too.
  if (d.c.info.closed && i == 0 && last >= 1) best = std::min(best, arc(last - 1, last));
  return best;
}

std::vector<PlanBall> ProtectionPlanner::separation_balls(bool record) const {
  // Every ball once: corners, then the samples of each curve between its ends
  // (a closed curve's first sample stands for its repeated last one).
  std::vector<PlanBall> balls;
  for (std::size_t q = 0; q < corners_.size(); ++q) {
    balls.push_back({corners_[q].point, corner_radius_[q], BallRef::at_corner(q),
                     record || corner_moved_[q] != 0});
  }
  for (std::size_t j = 0; j < curves_.size(); ++j) {
    const std::vector<BallSample>& s = curves_[j].samples;
    const std::size_t first = curves_[j].c.info.closed ? 0 : 1;
    for (std::size_t i = first; i + 1 < s.size(); ++i) {
      balls.push_back(
          {s[i].point, s[i].radius, BallRef::on_curve(j, i), record || curves_[j].moved});
    }
  }
  return balls;
}

bool ProtectionPlanner::consecutive_balls(const BallRef& a, const BallRef& b) const {
  if (!a.is_corner() && !b.is_corner() && a.curve() == b.curve()) {
    const CurveData& d = curves_[a.curve()];
    const int n = static_cast<int>(d.samples.size()) - 1;  // distinct samples
    const int gap = std::abs(a.sample() - b.sample());
    return gap == 1 || (d.c.info.closed && gap == n - 1);
  }
  if (a.is_corner() == b.is_corner()) return false;
  const BallRef& q = a.is_corner() ? a : b;
  const BallRef& s = a.is_corner() ? b : a;
  const CurveData& d = curves_[s.curve()];
  if (d.c.info.closed) return false;
  const int last = static_cast<int>(d.samples.size()) - 2;
  return (d.start == q.corner() && s.sample() == 1) || (d.end == q.corner() && s.sample() == last);
}

std::optional<ProtectionPlanner::PairShrink> ProtectionPlanner::pair_violation(
    const PlanBall& b, const PlanBall& o) const {
  const double dist = distance(b.center, o.center);
  const double need = disjoint_distance(b.radius, o.radius);
  if (dist >= need || consecutive_balls(b.ref, o.ref)) return std::nullopt;
  const bool related =
      related_balls(b.ref, o.ref, [&](int j) -> const CurveInfo& { return curves_[j].c.info; });
  if (related) {
    const double f = 0.95 * dist / need;
    return PairShrink{f, f};
  }
  // Unrelated features: overlapping balls are fine while each stays clear of
  // the other's feature; only one that does not shrinks.
  const double fb = feature_distance(o.ref, b.center) / ((1 + kGap) * b.radius);
  const double fo = feature_distance(b.ref, o.center) / ((1 + kGap) * o.radius);
  if (fb >= 1 && fo >= 1) return std::nullopt;
  return PairShrink{fb < 1 ? 0.95 * fb : 1.0, fo < 1 ? 0.95 * fo : 1.0};
}

void ProtectionPlanner::record_unresolved(const PlanBall& b, const PlanBall& o) {
  // Unresolved: at least neither ball may hold the other's centre.
  const double dist = distance(b.center, o.center);
  for (const BallRef& r : {b.ref, o.ref}) clamp_radius(r, 0.95 * dist);
  ++unresolved_pairs_;
  for (const BallRef& r : {b.ref, o.ref}) {
    for (const int j : curves_touching(r)) unresolved_curve_[j] = 1;
  }
  const std::string what = name(b.ref) + " near " + name(o.ref);
  if (unresolved_.size() < RefinementStats::kMaxListed &&
      std::find(unresolved_.begin(), unresolved_.end(), what) == unresolved_.end()) {
    unresolved_.push_back(what);
  }
}

bool ProtectionPlanner::separate_balls(bool record) {
  const std::vector<PlanBall> balls = separation_balls(record);
  if (balls.size() < 2) return false;
  const BallGrid grid(balls);
  std::vector<double> factor(balls.size(), 1.0);
  bool conflict = false;
  for (std::size_t k = 0; k < balls.size(); ++k) {
    deadline_.check(Deadline::kCheckEvery);
    grid.for_each_partner(k, [&](std::size_t other) {
      const std::optional<PairShrink> shrink = pair_violation(balls[k], balls[other]);
      if (!shrink) return;
      conflict = true;
      if (record) {
        record_unresolved(balls[k], balls[other]);
        return;
      }
      factor[k] = std::min(factor[k], shrink->first);
      factor[other] = std::min(factor[other], shrink->second);
    });
  }
  std::fill(corner_moved_.begin(), corner_moved_.end(), 0);
  for (CurveData& d : curves_) d.moved = false;
  if (!conflict || record) return false;
  bool changed = false;
  for (std::size_t k = 0; k < balls.size(); ++k) {
    if (factor[k] < 1) changed = shrink_ball(balls[k].ref, factor[k]) || changed;
  }
  return changed;
}

bool ProtectionPlanner::keep_off_patches() {
  if (oracle_ == nullptr) return false;
  bool changed = false;
  auto keep_off = [&](const BallRef& ref, const Point3& centre, double radius,
                      const std::vector<PatchId>& patches) {
    const double reach = kClearance * radius;
    const double d = oracle_->distance_to_other_patches(centre, patches, reach);
    // A patch within a few minimum sizes of the feature cannot be kept off (the
    // ball would reach the floor): refinement and its guard deal with it.
    if (d < reach && d >= kClearance * 4 * min_size_) {
      changed = shrink_ball(ref, std::max(0.95 * d / reach, 0.1), true) || changed;
    }
  };
  for (std::size_t q = 0; q < corners_.size(); ++q) {
    if (corner_clear_[q]) continue;
    corner_clear_[q] = 1;
    keep_off(BallRef::at_corner(q), corners_[q].point, corner_radius_[q], corners_[q].patches);
  }
  for (std::size_t j = 0; j < curves_.size(); ++j) {
    CurveData& d = curves_[j];
    if (d.clear) continue;
    d.clear = true;
    const std::size_t first = d.c.info.closed ? 0 : 1;
    for (std::size_t i = first; i + 1 < d.samples.size(); ++i) {
      keep_off(BallRef::on_curve(j, i), d.samples[i].point, d.samples[i].radius, d.c.info.patches);
    }
  }
  return changed;
}

void ProtectionPlanner::resolve() {
  // Every round shrinks some ball by a factor < 1 and no ball goes below the
  // minimum size, so the rounds end; the bound is a backstop.
  for (int round = 0; round < 1000; ++round) {
    deadline_.check(1);
    for (CurveData& d : curves_) {
      if (d.dirty) sample_curve(d);
      d.dirty = false;
    }
    bool changed = check_arcs();
    changed = separate_balls(false) || changed;
    // The oracle's queries cost more: only once the balls are otherwise fine.
    if (!changed) changed = keep_off_patches();
    if (!changed) break;
  }
  for (CurveData& d : curves_) {
    if (d.dirty) sample_curve(d);
    d.dirty = false;
  }
  unresolved_.clear();
  unresolved_pairs_ = 0;
  unresolved_curve_.assign(curves_.size(), 0);
  separate_balls(true);
  keep_all_visible();
}

ProtectionPlan ProtectionPlanner::plan() {
  resolve();
  return result();
}

bool ProtectionPlanner::shrink(const std::vector<BallRef>& balls, ProtectionPlan& plan) {
  bool changed = false;
  for (const BallRef& b : balls) {
    const bool known = b.is_corner()
                           ? b.corner() >= 0 && b.corner() < static_cast<int>(corners_.size())
                           : b.curve() >= 0 && b.curve() < static_cast<int>(curves_.size()) &&
                                 b.sample() >= 0 &&
                                 b.sample() < static_cast<int>(curves_[b.curve()].samples.size());
    if (!known) continue;
    changed = shrink_ball(b, b.factor) || changed;
  }
  if (!changed) return false;
  resolve();
  plan = result();
  return true;
}

ProtectionPlan ProtectionPlanner::result() const {
  ProtectionPlan plan;
  plan.corner_radius = corner_radius_;
  plan.unresolved = unresolved_;
  plan.unresolved_pairs = unresolved_pairs_;
  for (std::size_t j = 0; j < unresolved_curve_.size(); ++j) {
    if (unresolved_curve_[j]) plan.unresolved_curves.push_back(static_cast<int>(j));
  }
  plan.min_radius = std::numeric_limits<double>::infinity();
  plan.balls = corners_.size();
  for (double r : corner_radius_) plan.min_radius = std::min(plan.min_radius, r);
  for (const CurveData& d : curves_) {
    plan.curves.push_back(CurveProtection{d.samples});
    plan.balls += d.samples.size() - (d.c.info.closed ? 1 : 2);
    for (const BallSample& s : d.samples) plan.min_radius = std::min(plan.min_radius, s.radius);
  }
  if (!std::isfinite(plan.min_radius)) plan.min_radius = 0;
  return plan;
}

}  // namespace rdmesh::detail
