// Tests of ParametricCurve and PolylineCurve against analytic values.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <numbers>
#include <random>
#include <thread>

#include "oracles/error_of.h"
#include "rdmesh/errors.h"
#include "rdmesh/parametric_curve.h"
#include "rdmesh/polyline_curve.h"

namespace rdmesh {
namespace {

constexpr double kPi = std::numbers::pi;

ParametricCurve circle(double r, Point3 c = {}) {
  return ParametricCurve(
      [r, c](double t) {
        return c + Point3{r * std::cos(t), r * std::sin(t), 0};
      },
      0, 2 * kPi);
}

// Helix of radius r, pitch 2 pi b per turn: speed sqrt(r^2 + b^2).
ParametricCurve helix(double r, double b, double turns) {
  return ParametricCurve(
      [r, b](double t) {
        return Point3{r * std::cos(t), r * std::sin(t), b * t};
      },
      0, 2 * kPi * turns);
}

TEST(ParametricCurve, CircleLength) {
  for (double r : {1e-3, 0.3, 1.0, 250.0}) {
    const ParametricCurve c = circle(r, {1, 2, 3});
    EXPECT_TRUE(c.closed());
    EXPECT_NEAR(c.total_length(), 2 * kPi * r, 1e-10 * 2 * kPi * r) << r;
    EXPECT_NEAR(c.length(0, 2 * kPi), 2 * kPi * r, 1e-10 * 2 * kPi * r);
    EXPECT_NEAR(c.length(0.1, 0.1001), 0.0001 * r, 1e-10 * r);
    EXPECT_NEAR(c.length(0.3, 2.9), 2.6 * r, 1e-10 * r);
    EXPECT_NEAR(c.length(2.9, 0.3), -2.6 * r, 1e-10 * r);
  }
}

TEST(ParametricCurve, LengthIsAdditiveAndInvertible) {
  const ParametricCurve c = helix(0.7, 0.2, 3);
  const double speed = std::hypot(0.7, 0.2);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, c.t_end());
  for (int i = 0; i < 200; ++i) {
    double a = u(rng), b = u(rng), m = u(rng);
    if (a > b) std::swap(a, b);
    EXPECT_NEAR(c.length(a, b), speed * (b - a), 1e-10 * c.total_length());
    if (m > a && m < b) {
      EXPECT_NEAR(c.length(a, m) + c.length(m, b), c.length(a, b), 1e-12 * c.total_length());
    }
    const double s = c.length(a, b);
    EXPECT_NEAR(c.parameter_at_length(a, s), b, 1e-10 * c.t_end());
  }
  EXPECT_EQ(c.parameter_at_length(1.0, 0.0), 1.0);
  EXPECT_EQ(c.parameter_at_length(1.0, 1e9), c.t_end());
}

TEST(ParametricCurve, NonUniformSpeedLength) {
  // The parabola (t, t^2, 0), t in [0, 1]: length (2 sqrt 5 + asinh 2) / 4.
  const ParametricCurve c([](double t) { return Point3{t, t * t, 0}; }, 0, 1);
  const double exact = (2 * std::sqrt(5.0) + std::asinh(2.0)) / 4;
  EXPECT_NEAR(c.total_length(), exact, 1e-12);
  EXPECT_FALSE(c.closed());
  EXPECT_NEAR(c.parameter_at_length(0, c.length(0, 0.37)), 0.37, 1e-12);
}

TEST(ParametricCurve, ClosestOnCircleAndHelix) {
  const ParametricCurve c = circle(2.0);
  for (double angle : {0.1, 1.0, 2.5, 4.0, 6.0}) {
    const Point3 p{3 * std::cos(angle), 3 * std::sin(angle), 0.5};
    EXPECT_NEAR(c.closest(p, 0, 2 * kPi), angle, 1e-9) << angle;
    const Point3 inside{0.5 * std::cos(angle), 0.5 * std::sin(angle), -0.2};
    EXPECT_NEAR(c.closest(inside, 0, 2 * kPi), angle, 1e-9) << angle;
  }
  // Restricted range: the closest point of the arc is its nearer end.
  EXPECT_NEAR(c.closest({3, 0, 0}, 1.0, 2.0), 1.0, 1e-14);
  EXPECT_NEAR(c.closest({-3, 0, 0}, 1.0, 2.0), 2.0, 1e-14);
  const ParametricCurve h = helix(1.0, 0.1, 4);
  for (double t : {0.3, 5.0, 12.0, 20.0}) {
    const Point3 on = h.point(t);
    const Point3 p = on + 0.05 * Point3{std::cos(t), std::sin(t), 0};  // along the normal
    EXPECT_NEAR(h.closest(p, 0, h.t_end()), t, 1e-9) << t;
  }
}

TEST(ParametricCurve, PlaneCrossingsOfACircle) {
  const ParametricCurve c = circle(1.0);
  // x = 0.5 crosses at +-60 degrees.
  std::vector<double> x = c.plane_crossings({1, 0, 0}, 0.5, 0, 2 * kPi);
  ASSERT_EQ(x.size(), 2u);
  EXPECT_NEAR(x[0], kPi / 3, 1e-12);
  EXPECT_NEAR(x[1], 5 * kPi / 3, 1e-12);
  // Scaled normal: same plane.
  x = c.plane_crossings({3, 0, 0}, 1.5, 0, 2 * kPi);
  ASSERT_EQ(x.size(), 2u);
  EXPECT_NEAR(x[0], kPi / 3, 1e-12);
  // Nearly tangent plane: two crossings inside one table interval.
  const double d = 1 - 1e-8;
  x = c.plane_crossings({0, 1, 0}, d, 0, 2 * kPi);
  ASSERT_EQ(x.size(), 2u);
  EXPECT_NEAR(x[0], std::asin(d), 1e-9);
  EXPECT_NEAR(x[1], kPi - std::asin(d), 1e-9);
  EXPECT_TRUE(c.plane_crossings({0, 1, 0}, 1.0 + 1e-6, 0, 2 * kPi).empty());
  EXPECT_TRUE(c.plane_crossings({0, 0, 1}, 0.1, 0, 2 * kPi).empty());
  // Restricted range.
  x = c.plane_crossings({1, 0, 0}, 0.5, 0, kPi);
  ASSERT_EQ(x.size(), 1u);
  for (double t : c.plane_crossings({1, 1, 0.3}, 0.2, 0, 2 * kPi)) {
    EXPECT_NEAR(dot({1, 1, 0.3}, c.point(t)), 0.2, 1e-13);
  }
}

TEST(ParametricCurve, HelixCrossesHorizontalPlanesOnce) {
  const ParametricCurve h = helix(1.0, 0.1, 4);
  for (double z : {0.05, 0.7, 2.4}) {
    const std::vector<double> x = h.plane_crossings({0, 0, 1}, z, 0, h.t_end());
    ASSERT_EQ(x.size(), 1u) << z;
    EXPECT_NEAR(x[0], z / 0.1, 1e-11);
  }
  // The plane x = 0 crosses twice per turn.
  EXPECT_EQ(h.plane_crossings({1, 0, 0}, 0, 0, h.t_end()).size(), 8u);
}

TEST(ParametricCurve, LineFromExpressions) {
  const ParametricCurve line("1 + 2*t", "-t", "3", 0, 2);
  const double speed = std::sqrt(5.0);
  EXPECT_NEAR(line.total_length(), 2 * speed, 1e-10 * 2 * speed);
  EXPECT_EQ(line.point(1.0), (Point3{3, -1, 3}));
  EXPECT_NEAR(line.closest({3, -1, 10}, 0, 2), 1.0, 1e-13);
  EXPECT_NEAR(line.closest({-10, 0, 3}, 0, 2), 0.0, 1e-13);
  const std::vector<double> x = line.plane_crossings({1, 0, 0}, 2, 0, 2);
  ASSERT_EQ(x.size(), 1u);
  EXPECT_NEAR(x[0], 0.5, 1e-14);
  EXPECT_NEAR(line.parameter_at_length(0.5, speed), 1.5, 1e-11);
  const ParametricCurve c("0.3*cos(t)", "0.3*sin(t)", "0.953939", 0, 6.283185307179586);
  EXPECT_TRUE(c.closed());
  EXPECT_NEAR(c.total_length(), 0.6 * kPi, 1e-11);
}

TEST(ParametricCurve, Errors) {
  EXPECT_EQ(error_of([] { ParametricCurve("x", "0", "0", 0, 1); }),
            "x: unknown variable 'x' in 'x' (only t is defined)");
  EXPECT_NE(error_of([] { ParametricCurve("t", "cos(", "0", 0, 1); }).find("y: syntax error"),
            std::string::npos);
  EXPECT_NE(error_of([] { ParametricCurve("t", "0", "0", 1, 1); }).find("t0 < t1"),
            std::string::npos);
  EXPECT_NE(error_of([] { ParametricCurve("t", "0", "0", 0, INFINITY); }).find("finite"),
            std::string::npos);
  EXPECT_NE(error_of([] { ParametricCurve("sqrt(t)", "0", "0", -1, 1); }).find("not finite at t"),
            std::string::npos);
  EXPECT_NE(error_of([] { ParametricCurve(ParametricCurve::Function(), 0, 1); }).find("empty"),
            std::string::npos);
}

// Coordinates near the largest double make the finite-difference speed
// overflow: refused after a bounded number of evaluations (one Gauss-Legendre
// pair per interval), not after splitting every interval 12 times (found by the
// CLI campaign: a cube whose curve had x = 1e308 took a CPU-second to refuse).
TEST(ParametricCurve, AnOverflowingSpeedIsRefusedQuickly) {
  long evaluations = 0;
  const std::string e = error_of([&] {
    ParametricCurve(
        [&](double t) {
          ++evaluations;
          return Point3{1e308, t, 0.5};
        },
        -0.5, 0.5);
  });
  EXPECT_EQ(e.rfind("its arc length is not finite: coordinates up to 1e+308", 0), 0u) << e;
  // 64 intervals, 3 Gauss-Legendre rules of 5 speeds of at most 5 points each,
  // plus the sampling of the intervals: far below the 4096-fold split.
  EXPECT_LT(evaluations, 20000);
  EXPECT_GT(evaluations, 64);
}

TEST(ParametricCurve, ConcurrentQueriesAgree) {
  // Expression curves keep per-thread parsers: queries from several threads
  // give the same answers as from one.
  const ParametricCurve c("cos(t)", "sin(t)", "0.1*t", 0, 20);
  const double expected = c.closest({2, 0, 0.5}, 0, 20);
  std::vector<std::thread> threads;
  std::atomic<int> mismatches{0};
  for (int k = 0; k < 4; ++k) {
    threads.emplace_back([&] {
      for (int i = 0; i < 50; ++i) {
        if (c.closest({2, 0, 0.5}, 0, 20) != expected) ++mismatches;
      }
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(mismatches.load(), 0);
}

TEST(PolylineCurve, SquareQueries) {
  const PolylineCurve sq({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}});
  EXPECT_TRUE(sq.closed());
  EXPECT_EQ(sq.t_end(), 4.0);
  EXPECT_EQ(sq.point(1.5), (Point3{1, 0.5, 0}));
  EXPECT_EQ(sq.point(4.0), (Point3{0, 0, 0}));
  EXPECT_EQ(sq.length(0.5, 3.25), 2.75);
  EXPECT_EQ(sq.parameter_at_length(3.5, 2), 4.0);
  EXPECT_EQ(sq.parameter_at_length(0.5, 1), 1.5);
  EXPECT_DOUBLE_EQ(sq.closest({2, 0.25, 7}, 0, 4), 1.25);
  EXPECT_DOUBLE_EQ(sq.closest({0.5, -3, 0}, 0, 4), 0.5);
  EXPECT_DOUBLE_EQ(sq.closest({0.5, -3, 0}, 1, 3), 1.0);
  std::vector<double> x = sq.plane_crossings({1, 0, 0}, 0.25, 0, 4);
  ASSERT_EQ(x.size(), 2u);
  EXPECT_DOUBLE_EQ(x[0], 0.25);
  EXPECT_DOUBLE_EQ(x[1], 2.75);
  x = sq.plane_crossings({1, 0, 0}, 1.0, 0, 4);  // the side x = 1 lies in the plane
  ASSERT_EQ(x.size(), 1u);
  EXPECT_DOUBLE_EQ(x[0], 1.0);
}

TEST(PolylineCurve, DuplicatesAndErrors) {
  const PolylineCurve p({{0, 0, 0}, {0, 0, 0}, {3, 4, 0}});
  EXPECT_FALSE(p.closed());
  EXPECT_EQ(p.points().size(), 2u);
  EXPECT_EQ(p.t_end(), 5.0);
  EXPECT_NE(error_of([] { PolylineCurve({{1, 1, 1}}); }).find("two distinct"), std::string::npos);
  EXPECT_NE(error_of([] {
              PolylineCurve({{1, 1, 1}, {1, 1, 1}});
            }).find("two distinct"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              PolylineCurve({{0, 0, 0}, {1, 0, 0}, {0, 0, 0}});
            }).find("three"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              PolylineCurve({{0, NAN, 0}, {1, 0, 0}});
            }).find("not finite"),
            std::string::npos);
}

}  // namespace
}  // namespace rdmesh
