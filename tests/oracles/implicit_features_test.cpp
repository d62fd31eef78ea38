// Tests of ImplicitOracle's sharp features: declared curves, splitting, corners, patches.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "oracles/error_of.h"
#include "oracles/oracle_conformance.h"
#include "rdmesh/errors.h"
#include "rdmesh/implicit_oracle.h"
#include "rdmesh/parametric_curve.h"
#include "rdmesh/polyline_curve.h"

namespace rdmesh {
namespace {

constexpr double kPi = std::numbers::pi;
const Box3 kBox{{-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}};

double unit_sphere(const Point3& p) { return squared_norm(p) - 1; }

ImplicitOracle::CurveSpec circle_spec(std::string name, Point3 u, Point3 v, double r = 1) {
  auto c = std::make_shared<ParametricCurve>(
      [u, v, r](double t) { return r * std::cos(t) * u + r * std::sin(t) * v; }, 0, 2 * kPi);
  return {std::move(name), c, 0, 2 * kPi};
}

ImplicitOracle sphere_with(std::vector<ImplicitOracle::CurveSpec> curves) {
  return ImplicitOracle(kBox, {unit_sphere}, {}, {}, {}, std::move(curves));
}

TEST(ImplicitFeatures, NoCurves) {
  const ImplicitOracle o(kBox, {unit_sphere});
  EXPECT_TRUE(o.curves().empty());
  EXPECT_TRUE(o.corners().empty());
  EXPECT_THROW(o.curve(CurveId(1)), OracleError);
}

TEST(ImplicitFeatures, ClosedCurveHasNoCorner) {
  const ImplicitOracle o = sphere_with({circle_spec("equator", {1, 0, 0}, {0, 1, 0})});
  ASSERT_EQ(o.curves().size(), 1u);
  const CurveInfo c = o.curves()[0];
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.name, "equator");
  EXPECT_EQ(c.start, CornerId(0));
  EXPECT_EQ(c.end, CornerId(0));
  EXPECT_EQ(c.t_begin, 0.0);
  EXPECT_EQ(c.t_end, 2 * kPi);
  ASSERT_EQ(c.patches.size(), 1u);
  EXPECT_EQ(c.patches[0], o.patch_between(kOutside, SubdomainId(1)));
  EXPECT_TRUE(o.corners().empty());
  EXPECT_NEAR(o.curve(c.id).length(c.t_begin, c.t_end), 2 * kPi, 1e-10);
  expect_oracle_conformance(o, 300);
}

TEST(ImplicitFeatures, CrossingCirclesAreSplit) {
  // Equator and the meridian in the xz plane cross at (+-1, 0, 0).
  const ImplicitOracle o = sphere_with({circle_spec("equator", {1, 0, 0}, {0, 1, 0}),
                                        circle_spec("meridian", {1, 0, 0}, {0, 0, 1})});
  const std::vector<CurveInfo> curves = o.curves();
  const std::vector<CornerInfo> corners = o.corners();
  ASSERT_EQ(curves.size(), 4u);
  ASSERT_EQ(corners.size(), 2u);
  EXPECT_EQ(curves[0].name, "equator#1");
  EXPECT_EQ(curves[3].name, "meridian#2");
  for (const CornerInfo& q : corners) {
    EXPECT_NEAR(std::fabs(q.point.x), 1.0, 1e-12);
    EXPECT_EQ(q.curves.size(), 4u);
  }
  // The wrapping piece runs past 2 pi and still measures half a circle.
  double total = 0;
  for (const CurveInfo& c : curves) {
    EXPECT_FALSE(c.closed);
    EXPECT_NEAR(o.curve(c.id).length(c.t_begin, c.t_end), kPi, 1e-9) << c.name;
    total += c.t_end - c.t_begin;
  }
  EXPECT_NEAR(total, 4 * kPi, 1e-9);
  expect_oracle_conformance(o, 300);
}

TEST(ImplicitFeatures, CurveEndingOnAnotherSplitsIt) {
  // A quarter meridian from the north pole down to (1, 0, 0) on the equator.
  auto quarter = std::make_shared<ParametricCurve>(
      [](double t) {
        return Point3{std::sin(t), 0, std::cos(t)};
      },
      0, kPi / 2);
  const ImplicitOracle o = sphere_with(
      {circle_spec("equator", {0, 1, 0}, {-1, 0, 0}), {"quarter", quarter, 0, kPi / 2}});
  const std::vector<CurveInfo> curves = o.curves();
  ASSERT_EQ(curves.size(), 2u);
  ASSERT_EQ(o.corners().size(), 2u);
  EXPECT_EQ(curves[0].name, "equator");  // split once: one piece, from and to the junction
  EXPECT_FALSE(curves[0].closed);
  EXPECT_EQ(curves[0].start, curves[0].end);
  EXPECT_NEAR(curves[0].t_end - curves[0].t_begin, 2 * kPi, 1e-9);
  EXPECT_EQ(curves[1].end, curves[0].start);
  EXPECT_NEAR(distance(o.corners()[curves[0].start.value - 1].point, {1, 0, 0}), 0, 1e-12);
  expect_feature_conformance(o);
}

TEST(ImplicitFeatures, CubeEdgesAsAPolyline) {
  // Cube [-1, 1]^3 as six half-spaces; the boundary of its top face as one closed polyline.
  std::vector<ImplicitOracle::Function> f;
  for (int axis = 0; axis < 3; ++axis) {
    for (double s : {-1.0, 1.0}) {
      f.push_back([axis, s](const Point3& p) {
        return s * (axis == 0 ? p.x : axis == 1 ? p.y : p.z) - 1;
      });
    }
  }
  auto square = std::make_shared<PolylineCurve>(
      std::vector<Point3>{{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}, {-1, -1, 1}});
  const ImplicitOracle o(kBox, f, {{"cube", {0, 1, 2, 3, 4, 5}, {}}}, {}, {},
                         {{"top", square, square->t_begin(), square->t_end()}});
  ASSERT_EQ(o.curves().size(), 1u);
  EXPECT_TRUE(o.curves()[0].closed);
  EXPECT_TRUE(o.corners().empty());
  expect_feature_conformance(o);
}

TEST(ImplicitFeatures, Errors) {
  EXPECT_EQ(error_of([] {
              sphere_with({{"none", nullptr, 0, 1}});
            }),
            "curve 'none': no curve given");
  const ImplicitOracle::CurveSpec inner = circle_spec("inner", {1, 0, 0}, {0, 1, 0}, 0.5);
  const std::string off = error_of([&] { sphere_with({inner}); });
  EXPECT_EQ(off.rfind("curve 'inner' is not on the boundary of the domain", 0), 0u) << off;
  const std::string out = error_of([&] {
    sphere_with({circle_spec("big", {1, 0, 0}, {0, 1, 0}, 2)});
  });
  EXPECT_EQ(out.rfind("curve 'big': leaves the bounding box at t = 0", 0), 0u) << out;
  ImplicitOracle::CurveSpec bad = circle_spec("", {1, 0, 0}, {0, 1, 0});
  bad.t_end = NAN;
  EXPECT_NE(error_of([&] { sphere_with({bad}); }).find("curve 'curve_1': bad parameter range"),
            std::string::npos);
}

// A curve whose points all coincide is a point on the boundary: refused as
// input, before the protecting-ball planner finds it nothing to cover.
TEST(ImplicitFeatures, ACurveOfNoLengthIsAnInputError) {
  const auto dot = std::make_shared<ParametricCurve>([](double) { return Point3{1, 0, 0}; }, 0, 1);
  const std::string e = error_of([&] { sphere_with({{"dot", dot, 0, 1}}); });
  EXPECT_EQ(e.rfind("curve 'dot': it is a point, not a curve: its length 0 is not above the "
                    "tolerance",
                    0),
            0u)
      << e;
}

}  // namespace
}  // namespace rdmesh
