// Brent's safeguarded root finder (inverse quadratic interpolation, secant and
// bisection), written for the sign predicate g(t) < 0 rather than for g(t) == 0:
// it locates a point where the predicate changes, which is what a label change
// is. Header-only so that the callable is inlined (no std::function, no heap).
#pragma once

#include <cmath>
#include <limits>

namespace rdmesh::detail {

/// Result of brent_transition: the predicate g < 0 differs at `best` and `other`,
/// and |best - other| <= xtol (+ a few ulps).
struct Transition {
  double best;  ///< the end of the final bracket with the smaller |g|
  double g_best;
  double other;  ///< the other end of the final bracket
  double g_other;
  int evaluations;
};

/// Precondition: (g0 < 0) != (g1 < 0). Never evaluates g at t0 or t1 again.
/// Stops when the bracket is at most xtol wide, or after max_evaluations
/// (then the bracket is whatever was reached; bisection steps guarantee it
/// halves at least every third step).
template <class G>
Transition brent_transition(G&& g, double t0, double g0, double t1, double g1, double xtol,
                            int max_evaluations = 200) {
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  double a = t0, fa = g0, b = t1, fb = g1;
  double c = a, fc = fa;
  double d = b - a, e = d;
  int evaluations = 0;
  for (;;) {
    if ((fb < 0) == (fc < 0)) {  // keep c on the other side of the transition
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::fabs(fc) < std::fabs(fb)) {  // b is the best estimate
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol1 = 2 * kEps * std::fabs(b) + 0.5 * xtol;
    const double xm = 0.5 * (c - b);
    if (std::fabs(xm) <= tol1 || evaluations >= max_evaluations) {
      return {b, fb, c, fc, evaluations};
    }
    if (std::fabs(e) >= tol1 && std::fabs(fa) > std::fabs(fb)) {
      double p, q;
      const double s = fb / fa;
      if (a == c) {  // secant
        p = 2 * xm * s;
        q = 1 - s;
      } else {  // inverse quadratic interpolation
        const double qa = fa / fc, r = fb / fc;
        p = s * (2 * xm * qa * (qa - r) - (b - a) * (r - 1));
        q = (qa - 1) * (r - 1) * (s - 1);
      }
      if (p > 0) q = -q;
      p = std::fabs(p);
      const double min1 = 3 * xm * q - std::fabs(tol1 * q);
      const double min2 = std::fabs(e * q);
      if (2 * p < (min1 < min2 ? min1 : min2)) {
        e = d;
        d = p / q;
      } else {
        d = xm;
        e = d;
      }
    } else {
      d = xm;
      e = d;
    }
    a = b;
    fa = fb;
    b += std::fabs(d) > tol1 ? d : (xm > 0 ? tol1 : -tol1);
    fb = g(b);
    ++evaluations;
  }
}

}  // namespace rdmesh::detail
