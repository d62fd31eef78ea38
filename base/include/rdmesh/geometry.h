// Plain geometric value types shared by every layer of rdmesh.
//
// These types are deliberately free of CGAL so that oracles, writers and the
// CLI compile quickly; the refinement core converts at its boundary.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <compare>
#include <functional>
#include <initializer_list>

namespace rdmesh {

/// A point (or vector) in R^3.
struct Point3 {
  double x = 0, y = 0, z = 0;
  friend Point3 operator+(Point3 a, Point3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Point3 operator-(Point3 a, Point3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Point3 operator*(double s, Point3 a) { return {s * a.x, s * a.y, s * a.z}; }
  friend bool operator==(const Point3&, const Point3&) = default;
};

inline double dot(Point3 a, Point3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Point3 cross(Point3 a, Point3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double squared_norm(Point3 a) { return dot(a, a); }
inline double norm(Point3 a) { return std::sqrt(dot(a, a)); }
inline double distance(Point3 a, Point3 b) { return norm(a - b); }
inline bool is_finite(Point3 a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

/// Axis-aligned box [lo, hi].
struct Box3 {
  Point3 lo, hi;
  /// The empty box (lo = +inf, hi = -inf): growing it by points gives their box.
  static Box3 empty() {
    const double inf = HUGE_VAL;
    return {{inf, inf, inf}, {-inf, -inf, -inf}};
  }
  /// The smallest box containing `points` (a triangle's corners, say).
  static Box3 around(std::initializer_list<Point3> points) {
    Box3 b = empty();
    for (const Point3& p : points) b.grow(p);
    return b;
  }
  /// Enlarges the box to contain p.
  void grow(const Point3& p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  double diagonal() const { return distance(lo, hi); }
  Point3 center() const { return 0.5 * (lo + hi); }
  bool contains(Point3 p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }
};

/// Clips the line o + t d to `box` (slab test): narrows [lo, hi] to the t for
/// which the point lies in the box; false (lo, hi then meaningless) when that
/// range is empty. Pass [0, 1] for segment o, o + d, [-inf, inf] for the line.
inline bool clip_line(const Point3& o, const Point3& d, const Box3& box, double& lo, double& hi) {
  const double p[3] = {o.x, o.y, o.z}, v[3] = {d.x, d.y, d.z};
  const double bl[3] = {box.lo.x, box.lo.y, box.lo.z}, bh[3] = {box.hi.x, box.hi.y, box.hi.z};
  for (int k = 0; k < 3; ++k) {
    if (v[k] == 0) {
      if (p[k] < bl[k] || p[k] > bh[k]) return false;
      continue;
    }
    double ta = (bl[k] - p[k]) / v[k], tb = (bh[k] - p[k]) / v[k];
    if (ta > tb) std::swap(ta, tb);
    lo = std::max(lo, ta);
    hi = std::min(hi, tb);
    if (lo > hi) return false;
  }
  return true;
}

/// Strongly typed integer id: mixing a patch id with a subdomain id does not compile.
template <class Tag>
struct Id {
  int value = 0;
  constexpr Id() = default;
  constexpr explicit Id(int v) : value(v) {}
  friend constexpr auto operator<=>(const Id&, const Id&) = default;
};

/// Subdomain (cell C_l of the input complex). Value 0 means "outside the domain".
using SubdomainId = Id<struct SubdomainTag>;
/// Surface patch S_k. Ids start at 1.
using PatchId = Id<struct PatchTag>;
/// Curve segment L_j. Ids start at 1.
using CurveId = Id<struct CurveTag>;
/// Corner q in Q. Ids start at 1.
using CornerId = Id<struct CornerTag>;

inline constexpr SubdomainId kOutside{0};

/// A scalar field over R^3 (sizing field sigma, or any size criterion).
/// A constant field is evaluated without an indirect call.
struct ScalarField {
  double constant = 0.0;                       ///< used when `field` is empty
  std::function<double(const Point3&)> field;  ///< optional spatially varying value
  /// Whether `field` may be called from several threads at once. A field built
  /// from an arbitrary function is not (the refinement then evaluates it on one
  /// thread); rdmesh's own fields (expressions, gradings, thickness limits) are,
  /// and keep it through composition: see `composed`.
  bool concurrent = false;

  ScalarField() = default;
  /// A constant field (implicit: a number is a uniform field).
  ScalarField(double value) : constant(value) {}  // NOLINT(google-explicit-constructor)
  ScalarField(double value, std::function<double(const Point3&)> f, bool thread_safe = false)
      : constant(value), field(std::move(f)), concurrent(thread_safe) {}

  static ScalarField uniform(double v) { return ScalarField{v, {}}; }
  /// A field of `f`, callable from several threads at once when every field in
  /// `parts` is: for a field computed from other fields and read-only data.
  static ScalarField composed(std::function<double(const Point3&)> f,
                              std::initializer_list<const ScalarField*> parts) {
    bool thread_safe = true;
    for (const ScalarField* part : parts) thread_safe = thread_safe && part->is_concurrent();
    return ScalarField{0.0, std::move(f), thread_safe};
  }
  bool is_uniform() const { return !field; }
  /// True when the field may be evaluated from several threads at once.
  bool is_concurrent() const { return !field || concurrent; }
  double operator()(const Point3& p) const { return field ? field(p) : constant; }
};

}  // namespace rdmesh
