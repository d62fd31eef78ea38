// The sharp-feature part of the oracle conformance suite: curves and corners.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <sstream>

#include "oracles/oracle_conformance.h"
#include "rdmesh/errors.h"

namespace rdmesh {
namespace {

std::string str(const Point3& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return s.str();
}

Point3 unit(Point3 v) { return (1 / norm(v)) * v; }

/// Labels on a circle of radius r around curve point t, in the normal plane.
std::set<int> labels_around_curve(const DomainOracle& o, const Curve& c, const CurveInfo& info,
                                  double t, double r) {
  const double dt = 1e-6 * (info.t_end - info.t_begin);
  const Point3 tangent =
      unit(c.point(std::min(t + dt, info.t_end)) - c.point(std::max(t - dt, info.t_begin)));
  const Point3 axis = std::fabs(tangent.x) < 0.6 ? Point3{1, 0, 0} : Point3{0, 1, 0};
  const Point3 u = unit(cross(tangent, axis)), w = cross(tangent, u);
  std::set<int> out;
  const Point3 x = c.point(t);
  for (int k = 0; k < 64; ++k) {
    const double a = 2 * 3.141592653589793 * k / 64;
    out.insert(o.locate(x + (r * std::cos(a)) * u + (r * std::sin(a)) * w).label.value);
  }
  return out;
}

/// Labels on a sphere of radius r around x (Fibonacci directions).
std::set<int> labels_around_point(const DomainOracle& o, Point3 x, double r) {
  std::set<int> out;
  const int n = 400;
  for (int k = 0; k < n; ++k) {
    const double z = 1 - (2 * k + 1.0) / n, rho = std::sqrt(1 - z * z);
    const double phi = k * 2.399963229728653;
    out.insert(o.locate(x + r * Point3{rho * std::cos(phi), rho * std::sin(phi), z}).label.value);
  }
  return out;
}

bool has_sides(const std::set<int>& labels, const PatchInfo& p) {
  return labels.count(p.side_a.value) && labels.count(p.side_b.value);
}

const PatchInfo* find_patch(const std::vector<PatchInfo>& patches, PatchId id) {
  for (const PatchInfo& p : patches) {
    if (p.id == id) return &p;
  }
  return nullptr;
}

void check_topology(const std::vector<CurveInfo>& curves, const std::vector<CornerInfo>& corners) {
  const int m = static_cast<int>(corners.size());
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const CurveInfo& c = curves[i];
    EXPECT_EQ(c.id.value, static_cast<int>(i) + 1);
    EXPECT_FALSE(c.name.empty());
    EXPECT_LT(c.t_begin, c.t_end) << c.name;
    if (c.closed) {
      EXPECT_EQ(c.start.value, 0) << c.name;
      EXPECT_EQ(c.end.value, 0) << c.name;
      continue;
    }
    for (CornerId q : {c.start, c.end}) {
      ASSERT_TRUE(q.value >= 1 && q.value <= m)
          << "curve " << c.name << " ends at corner " << q.value;
      const std::vector<CurveId>& list = corners[q.value - 1].curves;
      EXPECT_NE(std::find(list.begin(), list.end(), c.id), list.end())
          << "corner " << q.value << " does not list curve " << c.name;
    }
  }
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const CornerInfo& q = corners[i];
    EXPECT_EQ(q.id.value, static_cast<int>(i) + 1);
    EXPECT_FALSE(q.curves.empty()) << "corner " << q.id.value << " ends no curve";
    for (CurveId id : q.curves) {
      ASSERT_TRUE(id.value >= 1 && id.value <= static_cast<int>(curves.size()));
      const CurveInfo& c = curves[id.value - 1];
      EXPECT_TRUE(!c.closed && (c.start == q.id || c.end == q.id))
          << "corner " << q.id.value << " lists curve " << c.name << " which does not end there";
    }
  }
}

void check_curve(const DomainOracle& o, const CurveInfo& info, std::mt19937& rng) {
  const Curve& c = o.curve(info.id);
  const double tol = o.tolerance(), diag = o.bounding_box().diagonal();
  const double range = info.t_end - info.t_begin;
  const std::vector<PatchInfo> patches = o.patches();
  const std::vector<CornerInfo> corners = o.corners();
  SCOPED_TRACE("curve " + info.name);
  // End points.
  if (info.closed) {
    EXPECT_LE(distance(c.point(info.t_begin), c.point(info.t_end)), tol);
  } else {
    EXPECT_LE(distance(c.point(info.t_begin), corners[info.start.value - 1].point), tol);
    EXPECT_LE(distance(c.point(info.t_end), corners[info.end.value - 1].point), tol);
  }
  // Incident patches: listed, and both sides of each occur around every point.
  EXPECT_FALSE(info.patches.empty());
  for (int k = 0; k < 8; ++k) {
    const double t = info.t_begin + range * (k + 0.5) / 8;
    const std::set<int> labels = labels_around_curve(o, c, info, t, 1e-5 * diag);
    EXPECT_GE(labels.size(), 2u) << "curve point " << str(c.point(t)) << " is not on the boundary";
    for (PatchId id : info.patches) {
      const PatchInfo* p = find_patch(patches, id);
      EXPECT_NE(p, nullptr) << "patch " << id.value << " is not listed";
      if (p) {
        EXPECT_TRUE(has_sides(labels, *p))
            << "curve point " << str(c.point(t)) << " not on " << p->name;
      }
    }
  }
  // Length: additive, positive, inverted by parameter_at_length.
  const double total = c.length(info.t_begin, info.t_end);
  EXPECT_GT(total, 0);
  std::uniform_real_distribution<double> u(info.t_begin, info.t_end);
  for (int k = 0; k < 10; ++k) {
    double a = u(rng), b = u(rng);
    if (a > b) std::swap(a, b);
    const double m = a + 0.3 * (b - a);
    EXPECT_NEAR(c.length(a, m) + c.length(m, b), c.length(a, b), 1e-9 * total + tol);
    EXPECT_NEAR(c.parameter_at_length(a, c.length(a, b)), b, 1e-8 * range) << a << " " << b;
  }
  EXPECT_EQ(c.parameter_at_length(info.t_begin, 2 * total), info.t_end);
  // closest: a point of the curve, at least as close as a known one.
  std::normal_distribution<double> gauss;
  for (int k = 0; k < 10; ++k) {
    const double t = u(rng);
    const Point3 x = c.point(t);
    const Point3 p = x + (1e-3 * diag) * unit({gauss(rng), gauss(rng), gauss(rng)});
    const double tc = c.closest(p, info.t_begin, info.t_end);
    EXPECT_GE(tc, info.t_begin);
    EXPECT_LE(tc, info.t_end);
    EXPECT_LE(distance(c.point(tc), p), distance(x, p) + tol) << "closest to " << str(p);
    EXPECT_NEAR(c.closest(x, info.t_begin, info.t_end), t, 1e-6 * range);
  }
  // plane_crossings: points on the plane; a plane through a curve point is found.
  for (int k = 0; k < 10; ++k) {
    const double t = u(rng);
    const Point3 n = unit({gauss(rng), gauss(rng), gauss(rng)});
    const double offset = dot(n, c.point(t));
    const std::vector<double> xs = c.plane_crossings(n, offset, info.t_begin, info.t_end);
    EXPECT_TRUE(std::is_sorted(xs.begin(), xs.end()));
    bool near = false;
    for (double x : xs) {
      EXPECT_LE(std::fabs(dot(n, c.point(x)) - offset), 10 * tol) << "crossing off the plane";
      near = near || distance(c.point(x), c.point(t)) <= 1e-6 * diag;
    }
    EXPECT_TRUE(near) << "the plane through " << str(c.point(t)) << " is not crossed there";
  }
}

void check_corner_patches(const DomainOracle& o, const CornerInfo& q) {
  const std::set<int> labels = labels_around_point(o, q.point, 1e-5 * o.bounding_box().diagonal());
  const std::vector<PatchInfo> patches = o.patches();  // find_patch points into it
  for (PatchId id : q.patches) {
    const PatchInfo* p = find_patch(patches, id);
    EXPECT_NE(p, nullptr) << "corner " << q.id.value << " patch " << id.value << " not listed";
    if (p) {
      EXPECT_TRUE(has_sides(labels, *p)) << "corner " << str(q.point) << " not on " << p->name;
    }
  }
  EXPECT_FALSE(q.patches.empty()) << "corner " << q.id.value;
}

/// Curves meet only at corners: a point of one curve on another is near a corner.
void check_meetings(const DomainOracle& o, const std::vector<CurveInfo>& curves,
                    const std::vector<CornerInfo>& corners) {
  const double diag = o.bounding_box().diagonal();
  for (const CurveInfo& a : curves) {
    for (const CurveInfo& b : curves) {
      if (a.id == b.id) continue;
      for (int k = 0; k <= 32; ++k) {
        const Point3 p = o.curve(a.id).point(a.t_begin + (a.t_end - a.t_begin) * k / 32);
        const Point3 q = o.curve(b.id).point(o.curve(b.id).closest(p, b.t_begin, b.t_end));
        if (distance(p, q) > 1e-7 * diag) continue;
        const bool at_corner =
            std::any_of(corners.begin(), corners.end(),
                        [&](const CornerInfo& c) { return distance(c.point, p) <= 1e-6 * diag; });
        EXPECT_TRUE(at_corner) << "curves " << a.name << " and " << b.name << " meet at " << str(p)
                               << ", which is not a corner";
      }
    }
  }
}

}  // namespace

void expect_feature_conformance(const DomainOracle& oracle, unsigned seed) {
  std::mt19937 rng(seed);
  const std::vector<CurveInfo> curves = oracle.curves();
  const std::vector<CornerInfo> corners = oracle.corners();
  check_topology(curves, corners);
  if (testing::Test::HasFatalFailure()) return;
  for (const CurveInfo& c : curves) check_curve(oracle, c, rng);
  for (const CornerInfo& q : corners) check_corner_patches(oracle, q);
  check_meetings(oracle, curves, corners);
  // The typed error of the interface, for ids on both sides of 1..n.
  EXPECT_THROW(oracle.curve(CurveId(static_cast<int>(curves.size()) + 1)), OracleError);
  EXPECT_THROW(oracle.curve(CurveId(0)), OracleError);
}

}  // namespace rdmesh
