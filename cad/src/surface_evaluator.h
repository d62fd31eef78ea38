// Internal to cad/: evaluation of one face's surface, and the two Newton solvers
// that refine a tessellation's guess on the true surface.
//
// A non-periodic B-spline surface is evaluated through one polynomial cache per
// (u, v) knot span, built on first use and kept; the span of (u, v) is chosen
// by a fixed rule (knot_i <= u < knot_i+1, end spans extended), so an
// evaluation is a function of (u, v) alone (queries are deterministic).
// Other surfaces go through GeomAdaptor_Surface, which caches one span of a
// B-spline (mutable state): within a few ulps of a knot its cached span and a
// freshly located one differ in the last bits, so there a fresh adaptor
// evaluates. Both kinds of cache are mutable state, so an evaluator is owned by
// one thread (ThreadState) or used only while the model is built.
#pragma once

#include <BSplSLib_Cache.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <optional>
#include <vector>

#include "rdmesh/geometry.h"

namespace rdmesh::cad {

struct FacePatch;

/// S(u, v) of a face's surface and its first and second derivatives.
class SurfaceEvaluator {
 public:
  explicit SurfaceEvaluator(const FacePatch& f);

  void d0(double u, double v, Point3& p) const;
  void d1(double u, double v, Point3& p, Point3& su, Point3& sv) const;
  void d2(double u, double v, Point3& p, Point3& su, Point3& sv, Point3& suu, Point3& svv,
          Point3& suv) const;
  /// Keeps an iterate where the surface is defined and near the face: periodic
  /// parameters are wrapped around the face's box, others are clamped to the box
  /// widened by a quarter of its size on each side (B-splines are extended by
  /// their end polynomials; other surfaces stop at their natural bounds).
  void confine(double& u, double& v) const;
  double u_period() const { return u_period_; }
  /// Whether evaluation goes through B-spline span caches.
  bool cached() const { return bspline_.has_value(); }
  /// The interior knots of a cached B-spline along u (or v); empty otherwise.
  std::vector<double> interior_knots(bool u) const;
  double v_period() const { return v_period_; }

 private:
  /// Whether (u, v) is so close to a knot that the span cache's history matters.
  bool near_break(double u, double v) const;
  /// Sets bspline_ up for a non-periodic B-spline with at most kMaxSpans spans.
  void build_spans();
  /// The B-spline's polynomial cache of the span holding (u, v), built on first use.
  const BSplSLib_Cache& span(double u, double v) const;
  /// Calls f(source) with the span cache, the adaptor or a fresh adaptor for (u, v).
  template <class F>
  void dispatch(double u, double v, F&& f) const;

  // The piecewise polynomial form of a non-periodic B-spline surface (spans_ empty otherwise).
  struct Spans {
    Handle(Geom_BSplineSurface) surface;
    TColStd_Array1OfReal u_flat, v_flat;  // knots with repetition
    TColgp_Array2OfPnt poles;
    std::optional<TColStd_Array2OfReal> weights;
    std::vector<double> u_knots, v_knots;  // distinct knots, increasing
  };
  std::optional<Spans> bspline_;
  mutable std::vector<Handle(BSplSLib_Cache)> spans_;  // (u span) * nv + (v span)

  Handle(Geom_Surface) surface_;
  GeomAdaptor_Surface adaptor_;
  std::vector<double> u_breaks_, v_breaks_;  // every knot (GeomAbs_CN breaks), sorted
  double u_first_ = 0, v_first_ = 0;         // start of the first period
  double u_lo_, u_hi_, v_lo_, v_hi_;         // clamp range of non-periodic parameters
  double u_mid_, v_mid_;                     // wrap centre of periodic ones
  double u_period_ = 0, v_period_ = 0;
};

/// A root of S(u, v) = a + w d found by Newton.
struct LineRoot {
  double u = 0, v = 0, w = 0;
  Point3 point;         ///< S(u, v)
  Point3 su, sv;        ///< derivatives at the root
  double residual = 0;  ///< |S(u, v) - (a + w d)|
  bool converged = false;
};

/// Newton on F(u, v, w) = S(u, v) - (a + w d) (Jacobian [Su Sv -d]) from the
/// guess, with step halving while |F| does not decrease and confine() after
/// each step. Converged when |F| <= tolerance.
LineRoot newton_on_line(const SurfaceEvaluator& s, const Point3& a, const Point3& d, double u,
                        double v, double w, double tolerance);

/// A local closest point of the surface to p.
struct SurfaceFoot {
  double u = 0, v = 0;
  Point3 point;
  bool converged = false;
};

/// Newton on the gradient of |S(u, v) - p|^2 / 2 (Gauss-Newton when the Hessian
/// is not positive definite), with step halving while the distance grows.
/// Converged when a step moves the foot by less than tolerance / 100, or when
/// no step descends and the tangential parts of p - S are below tolerance / 1000.
SurfaceFoot newton_foot(const SurfaceEvaluator& s, const Point3& p, double u, double v,
                        double tolerance);

}  // namespace rdmesh::cad
