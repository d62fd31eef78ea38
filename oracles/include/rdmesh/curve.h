// A curve segment L_j of the input complex (RR-7912 section 2): a smooth
// curve, open with its two endpoints at corners, or closed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rdmesh/geometry.h"

namespace rdmesh {

/// Description of a curve for the refinement core and the report.
struct CurveInfo {
  CurveId id;
  std::string name;
  bool closed = false;
  /// Parameter range [t_begin, t_end]; for a closed curve point(t_begin) == point(t_end).
  double t_begin = 0, t_end = 1;
  /// Corners at point(t_begin) and point(t_end); CornerId{0} for a closed curve.
  CornerId start, end;
  /// Patches whose closure contains the curve (the curve's incident patches).
  std::vector<PatchId> patches;
};

/// A corner q of Q: an endpoint of one or more curves.
struct CornerInfo {
  CornerId id;
  Point3 point;
  std::vector<CurveId> curves;   ///< curves ending at this corner
  std::vector<PatchId> patches;  ///< patches whose closure contains the corner
};

/// Exact queries on one curve. Parameters are those of CurveInfo; queries are
/// const and thread-safe. Accuracy: points within the oracle's tolerance().
class Curve {
 public:
  virtual ~Curve() = default;

  /// The point of parameter t in [t_begin, t_end].
  virtual Point3 point(double t) const = 0;

  /// Arc length between parameters ta <= tb.
  virtual double length(double ta, double tb) const = 0;

  /// The parameter t >= ta with length(ta, t) == s (clamped to t_end).
  virtual double parameter_at_length(double ta, double s) const = 0;

  /// The parameter of the point of the arc [ta, tb] closest to p.
  virtual double closest(const Point3& p, double ta, double tb) const = 0;

  /// Parameters in [ta, tb] where the arc crosses the plane dot(normal, x) == offset,
  /// ascending. Crossings closer than the tolerance may be reported once.
  virtual std::vector<double> plane_crossings(const Point3& normal, double offset, double ta,
                                              double tb) const = 0;

  /// The curvature at parameter t (1 / the radius of the osculating circle;
  /// 0 along a straight piece), for sizes that follow it (--curvature).
  virtual double curvature(double t) const = 0;
};

}  // namespace rdmesh
