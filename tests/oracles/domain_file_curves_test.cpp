// Tests of the "curves" key of the .json domain file and of the samples with sharp features.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "oracles/oracle_conformance.h"
#include "rdmesh/domain_file.h"
#include "rdmesh/errors.h"

namespace rdmesh {
namespace {

const std::string kSamples = std::string(RDMESH_SOURCE_DIR) + "/samples/";

struct Expected {
  const char* file;
  std::size_t subdomains, patches, curves, corners;
};

class FeatureSample : public testing::TestWithParam<Expected> {};

TEST_P(FeatureSample, LoadsConformsAndHasTheExpectedCounts) {
  const Expected e = GetParam();
  const LoadedDomain d = load_domain_file(kSamples + e.file);
  ASSERT_NE(d.oracle, nullptr);
  const DomainOracle& o = *d.oracle;
  EXPECT_EQ(o.subdomains().size(), e.subdomains);
  EXPECT_EQ(o.patches().size(), e.patches);
  EXPECT_EQ(o.curves().size(), e.curves);
  EXPECT_EQ(o.corners().size(), e.corners);
  expect_oracle_conformance(o, 400);
}

INSTANTIATE_TEST_SUITE_P(Samples, FeatureSample,
                         testing::Values(Expected{"capped_cylinder.json", 1, 3, 2, 0},
                                         Expected{"cube.json", 1, 6, 12, 8},
                                         Expected{"lens.json", 1, 2, 1, 0},
                                         Expected{"cylinder_through_ball.json", 2, 3, 2, 0},
                                         Expected{"wedge.json", 1, 3, 3, 2},
                                         Expected{"cone_tip.json", 1, 2, 1, 0}),
                         [](const auto& info) {
                           std::string name = info.param.file;
                           return name.substr(0, name.find('.'));
                         });

TEST(DomainFileCurves, CubeCornersJoinThreeEdges) {
  const LoadedDomain d = load_domain_file(kSamples + "cube.json");
  for (const CornerInfo& q : d.oracle->corners()) {
    EXPECT_EQ(q.curves.size(), 3u);
    EXPECT_EQ(q.patches.size(), 3u) << "a cube corner touches three faces";
    EXPECT_NEAR(std::fabs(q.point.x) + std::fabs(q.point.y) + std::fabs(q.point.z), 1.5, 1e-12);
  }
  EXPECT_EQ(d.oracle->corners()[0].point, (Point3{-0.5, -0.5, -0.5}));
  for (const CurveInfo& c : d.oracle->curves()) EXPECT_EQ(c.patches.size(), 2u) << c.name;
}

TEST(DomainFileCurves, CappedCylinderRimsSeparateSideAndCap) {
  const LoadedDomain d = load_domain_file(kSamples + "capped_cylinder.json");
  std::set<int> all;
  for (const CurveInfo& c : d.oracle->curves()) {
    ASSERT_EQ(c.patches.size(), 2u) << c.name;
    all.insert(c.patches[0].value);
    all.insert(c.patches[1].value);
  }
  EXPECT_EQ(all.size(), 3u) << "both rims share the side patch, each has its own cap";
}

TEST(DomainFileCurves, InterfaceCirclesTouchThreePatches) {
  const LoadedDomain d = load_domain_file(kSamples + "cylinder_through_ball.json");
  for (const CurveInfo& c : d.oracle->curves()) {
    EXPECT_TRUE(c.closed);
    EXPECT_EQ(c.patches.size(), 3u) << c.name;
    EXPECT_NEAR(d.oracle->curve(c.id).length(c.t_begin, c.t_end), 0.8 * M_PI, 1e-9);
  }
}

/// The error of a file with the unit ball and `curves`, written with ' for ".
std::string error_of(std::string curves) {
  std::replace(curves.begin(), curves.end(), '\'', '"');
  const std::string text =
      R"j({"bbox": [-2, -2, -2, 2, 2, 2], "functions": {"ball": "x^2 + y^2 + z^2 - 1"}, )j"
      R"j("curves": )j" +
      curves + "}";
  try {
    parse_domain_json(text, "test.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

void expect_error(const std::string& curves, const std::string& message) {
  const std::string got = error_of(curves);
  EXPECT_EQ(got.find('\n'), std::string::npos) << got;
  EXPECT_EQ(got.rfind("test.json: " + message, 0), 0u) << "got: " << got;
}

TEST(DomainFileCurves, Errors) {
  const std::string circle = "'x': 'cos(t)', 'y': 'sin(t)', 'z': '0', 't': [0, 6.283185307179586]";
  EXPECT_EQ(error_of("[{'name': 'eq', " + circle + "}]"), "no error");
  expect_error("{}", "'curves' must be a list of curves");
  expect_error("[3]", "curve 1 must be an object");
  expect_error("[{'name': ''}]", "curve 1: 'name' must be a non-empty string");
  expect_error("[{'name': 'eq', " + circle + "}, {'name': 'eq', " + circle + "}]",
               "two curves are named 'eq'");
  expect_error("[{'name': 'eq', 'w': 1, " + circle + "}]", "unknown key 'w' in curve 'eq'");
  expect_error("[{'name': 'rim'}]", "curve 'rim': give either");
  expect_error("[{'name': 'rim', 'points': [[1, 0, 0], [0, 1, 0]], " + circle + "}]",
               "curve 'rim': give either");
  expect_error("[{'name': 'rim', 'x': 't', 'y': '0', 't': [0, 1]}]",
               "curve 'rim': missing 'z' (an expression of t)");
  expect_error("[{'name': 'rim', 'x': 't', 'y': '0', 'z': 0, 't': [0, 1]}]",
               "curve 'rim': 'z' must be an expression string of t");
  expect_error("[{'name': 'rim', 'x': 't', 'y': '0', 'z': '0'}]", "curve 'rim': missing 't'");
  expect_error("[{'name': 'rim', 'x': 't', 'y': '0', 'z': '0', 't': [1, 0]}]",
               "curve 'rim': 't' must be [t0, t1] with finite numbers t0 < t1, got [1,0]");
  expect_error("[{'name': 'rim', 'x': 't', 'y': '0', 'z': '0', 't': [0]}]",
               "curve 'rim': 't' must be [t0, t1]");
  expect_error("[{'name': 'rim', 'x': 'cos(x)', 'y': 'sin(t)', 'z': '0', 't': [0, 1]}]",
               "curve 'rim': x: unknown variable 'x' in 'cos(x)' (only t is defined)");
  expect_error("[{'name': 'rim', 'x': 'cos(t)', 'y': 'sin(t', 'z': '0', 't': [0, 1]}]",
               "curve 'rim': y: syntax error in 'sin(t'");
  expect_error("[{'name': 'rim', 'x': 'cos(t)', 'y': 'foo(t)', 'z': '0', 't': [0, 1]}]",
               "curve 'rim': y: unknown function 'foo'");
  expect_error("[{'name': 'p', 'points': [[1, 0, 0]]}]",
               "curve 'p': 'points' must be a list of at least two [x, y, z] points");
  expect_error("[{'name': 'p', 'points': [[1, 0, 0], [1, 0]]}]",
               "curve 'p': point 1 must be [x, y, z] (three numbers)");
  expect_error("[{'name': 'p', 'points': [[1, 0, 0], [1, 0, 0]]}]",
               "curve 'p': a polyline needs at least two distinct points");
  // Constant coordinates, or a 't' range below double's resolution: a point.
  expect_error("[{'name': 'dot', 'x': '1', 'y': '0', 'z': '0', 't': [0, 1]}]",
               "curve 'dot': it is a point, not a curve: its 4097 sampled points all lie within 0 "
               "of (1, 0, 0)");
  expect_error(
      "[{'name': 'dot', 'x': 'cos(t)', 'y': 'sin(t)', 'z': '0', 't': [1, "
      "1.0000000000000002]}]",
      "curve 'dot': it is a point, not a curve");
  // A polyline on the sphere's equator would cut through the ball: off the boundary.
  expect_error("[{'points': [[1, 0, 0], [0, 1, 0]]}]",
               "curve 'curve_1' is not on the boundary of the domain");
  expect_error("[{'name': 'inner', 'x': '0.5*cos(t)', 'y': '0.5*sin(t)', 'z': '0', 't': [0, 6]}]",
               "curve 'inner' is not on the boundary of the domain");
  expect_error("[{'name': 'far', 'x': '3*cos(t)', 'y': '3*sin(t)', 'z': '0', 't': [0, 1]}]",
               "curve 'far': leaves the bounding box at t = 0");
}

}  // namespace
}  // namespace rdmesh
