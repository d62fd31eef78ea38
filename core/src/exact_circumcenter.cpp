// Circumcenters (and orthocenters of weighted points) of nearly flat
// tetrahedra, where the double formulas of simplex_geometry.h lose their
// digits. First in double-double arithmetic (about 106 bits, error-free
// transformations, no allocation); when even that leaves too few digits, with
// CGAL's exact rationals. Kept in its own translation unit: the exact kernel
// is slow to compile.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <optional>

#include "simplex_geometry.h"

namespace rdmesh::detail {
namespace {

/// Exactly coplanar: decided by Epick's filtered predicate on the doubles
/// themselves, without building the exact kernel's lazy (allocated) points.
/// Flat cells are common (four vertices on one planar face of a triangle
/// mesh), and their centre is at infinity.
bool flat(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  using K = CGAL::Epick;
  const auto p = [](const Point3& q) { return K::Point_3(q.x, q.y, q.z); };
  return CGAL::coplanar(p(a), p(b), p(c), p(d));
}

// --- Double-double numbers: value = hi + lo, |lo| <= ulp(hi) / 2 ---
struct DD {
  double hi = 0, lo = 0;
};
DD two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
DD quick_two_sum(double a, double b) {  // |a| >= |b|
  const double s = a + b;
  return {s, b - (s - a)};
}
DD operator+(DD a, DD b) {
  DD s = two_sum(a.hi, b.hi);
  const DD t = two_sum(a.lo, b.lo);
  s.lo += t.hi;
  s = quick_two_sum(s.hi, s.lo);
  s.lo += t.lo;
  return quick_two_sum(s.hi, s.lo);
}
DD operator-(DD a) { return {-a.hi, -a.lo}; }
DD operator-(DD a, DD b) { return a + (-b); }
DD operator*(DD a, DD b) {
  const double p = a.hi * b.hi;
  const double e = std::fma(a.hi, b.hi, -p) + (a.hi * b.lo + a.lo * b.hi);
  return quick_two_sum(p, e);
}

struct DD3 {
  DD x, y, z;
};
DD3 difference(const Point3& a, const Point3& b) {  // exact
  return {two_sum(a.x, -b.x), two_sum(a.y, -b.y), two_sum(a.z, -b.z)};
}
DD dot(const DD3& a, const DD3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
DD3 cross(const DD3& a, const DD3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
DD3 operator*(DD s, const DD3& a) { return {s * a.x, s * a.y, s * a.z}; }
DD3 operator+(const DD3& a, const DD3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }

/// n / d rounded to double (one correction step).
double quotient(DD n, DD d) {
  const double q = n.hi / d.hi;
  const DD r = n - DD{q, 0} * d;
  return q + r.hi / d.hi;
}

/// The orthocenter in double-double: p0 + (b0 vx + b1 xu + b2 uv) / (2 det).
/// The rounding error of det is below 1e-30 of M = |u| |v| |x| (a few dozen
/// operations at 2^-104), so where |det| >= 1e-18 M the centre is good to
/// about 1e-12 of its distance (better than the double formula's 1e-10 at
/// its own threshold). nullopt below that: the exact path decides.
std::optional<Point3> double_double_orthocenter(const std::array<Point3, 4>& p,
                                                const std::array<double, 4>& w) {
  const DD3 u = difference(p[1], p[0]), v = difference(p[2], p[0]), x = difference(p[3], p[0]);
  const DD3 vx = cross(v, x), xu = cross(x, u), uv = cross(u, v);
  const DD det = dot(u, vx);
  const double m =
      std::sqrt(squared_norm(p[1] - p[0]) * squared_norm(p[2] - p[0]) * squared_norm(p[3] - p[0]));
  if (!(std::fabs(det.hi) >= 1e-18 * m)) return std::nullopt;
  const DD w0{w[0], 0};
  const DD b0 = dot(u, u) - DD{w[1], 0} + w0, b1 = dot(v, v) - DD{w[2], 0} + w0,
           b2 = dot(x, x) - DD{w[3], 0} + w0;
  const DD3 num = b0 * vx + b1 * xu + b2 * uv;
  const DD twice{2 * det.hi, 2 * det.lo};
  return Point3{p[0].x + quotient(num.x, twice), p[0].y + quotient(num.y, twice),
                p[0].z + quotient(num.z, twice)};
}

constexpr double kInf = std::numeric_limits<double>::infinity();

/// The exact point rounded to doubles. (CGAL::to_double on a lazy number
/// may return its interval's midpoint when the interval is within 1e-5.)
template <class P>
Point3 rounded(const P& z) {
  return {CGAL::to_double(z.x().exact()), CGAL::to_double(z.y().exact()),
          CGAL::to_double(z.z().exact())};
}

}  // namespace

Point3 exact_tet_orthocenter(const std::array<Point3, 4>& p, const std::array<double, 4>& w) {
  if (flat(p[0], p[1], p[2], p[3])) return {kInf, kInf, kInf};
  if (const auto z = double_double_orthocenter(p, w)) return *z;
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  const auto wp = [&](int i) {
    return EK::Weighted_point_3(EK::Point_3(p[i].x, p[i].y, p[i].z), w[i]);
  };
  const EK::Point_3 z = CGAL::weighted_circumcenter(wp(0), wp(1), wp(2), wp(3));
  return rounded(z);
}

}  // namespace rdmesh::detail
