// The caps of one protected curve: point constraints (arc a_k, value v_k) on the
// step size that spread as v_k + growth |a - a_k| (protection.h). The planner
// asks for the caps near an arc length, and only those: a cap at distance d
// constrains a step to at least growth * d / (1 + growth) whatever its value, so
// the caps beyond a distance that bounds the answer cannot change it. Kept
// sorted by arc length, a query costs a binary search plus the caps that matter:
// a needle shrunk ball by ball used to cost every cap of its curve per sample,
// quadratic in the number of shrinks (34,711 balls took 42 s). The answers are
// the same doubles as a scan over every cap: a minimum does not depend on the
// order it is taken in.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace rdmesh::detail {

class SizeCaps {
 public:
  struct Cap {
    double arc, value;
  };

  bool empty() const { return caps_.empty(); }
  std::size_t size() const { return caps_.size(); }

  void add(double arc, double value) {
    const auto at = std::upper_bound(caps_.begin(), caps_.end(), arc,
                                     [](double x, const Cap& c) { return x < c.arc; });
    caps_.insert(at, {arc, value});
  }

  /// Calls f(cap) for every cap whose arc lies in [lo, hi] (and possibly a few
  /// more: callers take minima).
  template <class F>
  void for_each_in(double lo, double hi, F&& f) const {
    auto it = std::lower_bound(caps_.begin(), caps_.end(), lo,
                               [](const Cap& c, double x) { return c.arc < x; });
    for (; it != caps_.end() && it->arc <= hi; ++it) f(*it);
  }

  /// Calls f(cap) for every cap within arc distance `reach` of a on a curve of
  /// length `length`, around its closing point too when `closed`.
  template <class F>
  void for_each_near(double a, double reach, bool closed, double length, F&& f) const {
    if (!(reach < HUGE_VAL) || (closed && 2 * reach >= length)) {
      for (const Cap& c : caps_) f(c);
      return;
    }
    for_each_in(a - reach, a + reach, f);
    if (!closed) return;
    // Arcs lie in [0, length]: the window's parts beyond either end, wrapped
    // (a cap in both parts is visited twice).
    if (a + reach > length) for_each_in(-HUGE_VAL, a + reach - length, f);
    if (a - reach < 0) for_each_in(a - reach + length, HUGE_VAL, f);
  }

  /// min over the caps of value + growth |arc - x| (HUGE_VAL without caps): the
  /// caps' size at x along the curve, ignoring its closing point.
  double lowest_at(double x, double growth) const {
    double now = HUGE_VAL;
    const auto mid = std::lower_bound(caps_.begin(), caps_.end(), x,
                                      [](const Cap& c, double v) { return c.arc < v; });
    // Outwards on both sides; a cap at distance d gives at least growth * d,
    // so a side stops once that passes the minimum so far (halved: rounding).
    for (auto it = mid; it != caps_.end(); ++it) {
      if (0.5 * growth * (it->arc - x) > now) break;
      now = std::min(now, it->value + growth * std::fabs(it->arc - x));
    }
    for (auto it = mid; it != caps_.begin();) {
      --it;
      if (0.5 * growth * (x - it->arc) > now) break;
      now = std::min(now, it->value + growth * std::fabs(it->arc - x));
    }
    return now;
  }

 private:
  std::vector<Cap> caps_;  ///< by arc length; equal arcs in insertion order
};

}  // namespace rdmesh::detail
