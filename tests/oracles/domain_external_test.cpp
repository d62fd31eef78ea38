// Domain documents with functions and curves given as code (ExternalDefinitions,
// what the Python module passes) and the batch evaluation of the sampling grid.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "rdmesh/domain_file.h"
#include "rdmesh/errors.h"
#include "rdmesh/parametric_curve.h"

namespace rdmesh {
namespace {

double ball(const Point3& p) { return p.x * p.x + p.y * p.y + p.z * p.z - 1; }

const std::string kBall =
    R"({"bbox": [-2, -2, -2, 2, 2, 2], "functions": {"ball": "x^2 + y^2 + z^2 - 1"}})";
const std::string kExternalBall =
    R"({"bbox": [-2, -2, -2, 2, 2, 2], "functions": {"ball": {"external": "f"}}})";

std::string error_of(const std::string& text, const ExternalDefinitions& external) {
  try {
    parse_domain_json(text, "doc", external);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(DomainExternal, SameDomainAsTheExpression) {
  ExternalDefinitions external;
  external.functions["f"] = {ball, {}};
  const LoadedDomain code = parse_domain_json(kExternalBall, "doc", external);
  const LoadedDomain text = parse_domain_json(kBall, "doc");
  EXPECT_EQ(code.oracle->patches().size(), 1u);
  EXPECT_EQ(code.oracle->subdomains()[0].name, "ball");
  for (double t = -1.9; t < 1.9; t += 0.0371) {
    const Point3 p{t, 0.3 * t, -0.2};
    EXPECT_EQ(code.oracle->locate(p).label, text.oracle->locate(p).label);
  }
  const auto hit = code.oracle->intersect({0, 0, 0}, {1.5, 0, 0});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->point.x, 1.0, 1e-9);
}

TEST(DomainExternal, BatchLabelsTheGridOnce) {
  int batch_calls = 0;
  std::size_t batch_points = 0;
  ExternalDefinitions external;
  external.functions["f"] = {ball,
                             [&](const std::vector<Point3>& points, std::vector<double>& out) {
                               ++batch_calls;
                               batch_points = points.size();
                               out.clear();
                               for (const Point3& p : points) out.push_back(ball(p));
                             }};
  const LoadedDomain code = parse_domain_json(kExternalBall, "doc", external);
  EXPECT_EQ(batch_calls, 1);
  EXPECT_EQ(batch_points, 49u * 49u * 49u);
  // The same initial points as point-by-point sampling.
  ExternalDefinitions plain;
  plain.functions["f"] = {ball, {}};
  const LoadedDomain point = parse_domain_json(kExternalBall, "doc", plain);
  const auto a = code.oracle->initial_points(PatchId(1));
  const auto b = point.oracle->initial_points(PatchId(1));
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(distance(a[i], b[i]), 0.0);
}

TEST(DomainExternal, WrongBatchSizeIsAnInputError) {
  ExternalDefinitions external;
  external.functions["f"] = {
      ball, [](const std::vector<Point3>&, std::vector<double>& out) { out.assign(10, -1.0); }};
  EXPECT_NE(error_of(kExternalBall, external).find("returned 10 values for 117649 points"),
            std::string::npos);
}

TEST(DomainExternal, Errors) {
  ExternalDefinitions external;
  external.functions["f"] = {ball, {}};
  // A domain file never accepts them.
  try {
    parse_domain_json(kExternalBall, "file.json");
    FAIL() << "accepted an external function without definitions";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "file.json: function 'ball' must be an expression string");
  }
  EXPECT_EQ(error_of(R"({"bbox": [-2, -2, -2, 2, 2, 2], "functions": {"ball": {"external": "g"}}})",
                     external),
            "doc: function 'ball': no external function 'g'");
  EXPECT_EQ(error_of(R"({"bbox": [-2, -2, -2, 2, 2, 2], "functions": {"ball": {"extern": "f"}}})",
                     external),
            "doc: function 'ball' must be an expression string or {\"external\": KEY}");
  EXPECT_NE(error_of(R"({"bbox": [-2, -2, -2, 2, 2, 2], "functions": {"ball": {"external": "f"}},
                         "curves": [{"name": "c", "external": "nope"}]})",
                     external)
                .find("curve 'c': no external curve 'nope'"),
            std::string::npos);
}

TEST(DomainExternal, CurveGivenAsCode) {
  // A capped cylinder's top rim as code, the rest as text.
  const std::string doc = R"({"bbox": [-0.8, -0.8, -0.9, 0.8, 0.8, 0.9],
    "functions": {"side": "x^2 + y^2 - 0.25", "top": "z - 0.6", "bottom": "-z - 0.6"},
    "subdomains": [{"name": "cylinder", "inside": ["side", "top", "bottom"]}],
    "curves": [{"name": "rim", "external": "top"}]})";
  ExternalDefinitions external;
  const double two_pi = 2 * std::numbers::pi;
  external.curves["top"] = {"",
                            std::make_shared<ParametricCurve>(
                                [](double t) {
                                  return Point3{0.5 * std::cos(t), 0.5 * std::sin(t), 0.6};
                                },
                                0.0, two_pi),
                            0.0, two_pi};
  const LoadedDomain d = parse_domain_json(doc, "doc", external);
  ASSERT_EQ(d.oracle->curves().size(), 1u);
  EXPECT_EQ(d.oracle->curves()[0].name, "rim");
  EXPECT_EQ(d.oracle->curves()[0].patches.size(), 2u);  // the side and the top
}

}  // namespace
}  // namespace rdmesh
