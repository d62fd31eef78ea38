// A smooth parametric curve t -> gamma(t), t in [t0, t1], given by a C++
// callable or by three expressions of t.
//
// Construction samples the curve adaptively (at least 64 intervals, split until
// consecutive chords turn by less than ~6 degrees and the chord follows the arc
// within 1% of its length) and integrates the arc length of every interval.
// The table is immutable afterwards: every query is const and thread-safe, and
// point() allocates nothing (beyond what the callable itself does).
//
// Accuracy: length() ~1e-10 relative (adaptive 5-point Gauss-Legendre on |gamma'|,
// gamma' by 4th-order finite differences, one-sided near the ends so that gamma is
// never evaluated outside [t0, t1]); parameter_at_length, closest and
// plane_crossings solve for parameters to ~1e-14 (t1 - t0).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rdmesh/curve.h"

namespace rdmesh {

class ParametricCurve final : public Curve {
 public:
  /// t -> gamma(t). Must be deterministic, thread-safe, smooth (C^2) and finite on [t0, t1].
  using Function = std::function<Point3(double)>;

  /// Throws InputError for an empty function, a range that is not finite with
  /// t0 < t1, or a non-finite point at a sample parameter.
  ParametricCurve(Function gamma, double t0, double t1);

  /// The curve (x(t), y(t), z(t)) from three expressions of the single variable t
  /// (syntax of rdmesh/expression.h). Throws InputError as Expression does
  /// ("unknown variable 'x' in 'x+t' (only t is defined)"), prefixed by "x: ",
  /// "y: " or "z: ", and as the other constructor.
  ParametricCurve(const std::string& x, const std::string& y, const std::string& z, double t0,
                  double t1);

  double t_begin() const { return t0_; }
  double t_end() const { return t1_; }
  /// Total arc length over [t0, t1].
  double total_length() const { return cumulative_.back(); }
  /// True when gamma(t0) and gamma(t1) are within 1e-10 of the curve's extent.
  bool closed() const { return closed_; }

  /// gamma(t), t clamped to [t0, t1].
  Point3 point(double t) const override;
  /// Arc length between ta <= tb (both clamped to [t0, t1]); negative when ta > tb.
  double length(double ta, double tb) const override;
  /// Safeguarded Newton (bisection fallback) on the cumulative length. s <= 0 gives ta.
  double parameter_at_length(double ta, double s) const override;
  /// Sign changes of dot(gamma - p, gamma') on the sample table, solved by Brent;
  /// the best of these and of ta, tb. Global within [ta, tb] as long as the
  /// table resolves the curve (see the file comment).
  double closest(const Point3& p, double ta, double tb) const override;
  /// Sign changes of dot(normal, gamma) - offset on the sample table, solved by
  /// Brent; intervals where the curve could touch the plane without a sign
  /// change at their ends are subdivided (bound from the measured chord deviation).
  std::vector<double> plane_crossings(const Point3& normal, double offset, double ta,
                                      double tb) const override;

  /// |gamma' x gamma''| / |gamma'|^3, both derivatives by finite differences
  /// (gamma'' of 4th order, 2nd order one-sided near the ends) with the step
  /// of derivative().
  double curvature(double t) const override;

  /// gamma'(t) by finite differences (4th order), never evaluating outside [t0, t1].
  Point3 derivative(double t) const;

 private:
  void build_table();
  double speed(double t) const { return norm(derivative(t)); }
  /// Arc length over [a, b] inside one table interval (adaptive Gauss-Legendre).
  double integrate(double a, double b, double whole, int depth) const;
  /// Cumulative length from t0 to t.
  double cumulative_at(double t) const;
  /// Index i of the table interval [t_i, t_i+1] containing t.
  std::size_t interval_of(double t) const;
  /// Sample parameters covering [ta, tb]: ta, the table parameters inside, tb (at least 16).
  void samples_between(double ta, double tb, std::vector<double>& out) const;
  double clamp(double t) const { return t < t0_ ? t0_ : (t > t1_ ? t1_ : t); }

  Function gamma_;
  double t0_, t1_;
  double noise_ = 0;  // absolute tolerance floor of integrate()
  bool closed_ = false;
  std::vector<double> params_;      // table parameters, params_[0] = t0, back() = t1
  std::vector<double> cumulative_;  // arc length from t0 to params_[i]
  std::vector<double> deviation_;   // per interval: bound on the distance of the arc to its chord
};

}  // namespace rdmesh
