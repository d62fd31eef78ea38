// Limits of the domain file (issue 23): nesting, sizes of lists and expressions,
// boxes double precision cannot mesh, domains reaching their box, runaway curves.
#include <gtest/gtest.h>

#include <string>

#include "rdmesh/domain_file.h"
#include "rdmesh/errors.h"

namespace rdmesh {
namespace {

const std::string kBallIn2 = R"("bbox": [-2,-2,-2,2,2,2], "functions": {"b": "x^2+y^2+z^2-1"})";

/// Expects parsing `text` to throw an InputError "limits.json: ..." containing `part`.
void expect_refused(const std::string& text, const std::string& part) {
  try {
    parse_domain_json(text, "limits.json");
    ADD_FAILURE() << "accepted: " << text.substr(0, 200);
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("limits.json: ", 0), 0u) << m;
    EXPECT_NE(m.find(part), std::string::npos) << "'" << part << "' not in: " << m;
  }
}

std::string repeated(const std::string& item, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out.append(i ? ", " : "").append(item);
  return out;
}

TEST(DomainFileLimits, NestingIsCountedOutsideStringsAndComments) {
  const std::string brackets(1000, '[');
  EXPECT_NO_THROW(parse_domain_json("// " + brackets + "\n/* " + brackets + " */ {" + kBallIn2 +
                                        R"(, "description": ")" + brackets + "\"}",
                                    "limits.json"));
  expect_refused(
      "{" + kBallIn2 + R"(, "size": )" + std::string(65, '[') + "1" + std::string(65, ']') + "}",
      "nested deeper than 64 levels");
}

TEST(DomainFileLimits, ListsAndExpressionsAreBounded) {
  const std::string subdomain = R"({"inside": ["b"]})";
  expect_refused("{" + kBallIn2 + R"(, "subdomains": [)" + repeated(subdomain, 65) + "]}",
                 "too many subdomains (65), at most 64");
  const std::string point = "[0, 0, 1]";
  expect_refused("{" + kBallIn2 + R"(, "curves": [{"points": [)" + repeated(point, 100001) + "]}]}",
                 "too many points (100001), at most 100000");
  expect_refused("{" + kBallIn2 + R"(, "curves": [)" +
                     repeated(R"({"points": [[0,0,1],[0,1,0]]})", 1001) + "]}",
                 "too many curves (1001), at most 1000");
  std::string sum = "0.1";
  for (int i = 0; i < 5000; ++i) sum += "+0";
  expect_refused("{" + kBallIn2 + R"(, "size": ")" + sum + "\"}",
                 "'size': the expression is 10003 characters long, at most 10000");
}

TEST(DomainFileLimits, BoxesDoublePrecisionCannotMeshAreRefused) {
  const std::string f = R"(, "functions": {"b": "x^2+y^2+z^2-1e-20"}})";
  expect_refused(R"({"bbox": [-1e-9,-1e-9,-1e-9,1e-9,1e-9,1e-9])" + f, "below 1e-6");
  expect_refused(R"({"bbox": [-100,-100,-1e-5,100,100,1e-5])" + f, "the box is flat");
  expect_refused(R"({"bbox": [1e9,1e9,1e9,1000000001,1000000001,1000000001])" + f,
                 "double precision");
}

TEST(DomainFileLimits, DomainsReachingTheBoxAreRefused) {
  expect_refused(R"({"bbox": [-1,-1,-1,1,1,1], "functions": {"b": "-1"}})",
                 "the domain reaches the bounding box: (-1, -1, -1)");
  expect_refused(R"({"bbox": [-1,-1,-1,1,1,1], "functions": {"b": "z - 0.5"}})",
                 "inside subdomain 'b'");
  // Touching the box at single points of its faces' centres is not reaching it.
  EXPECT_NO_THROW(parse_domain_json(
      R"({"bbox": [-1,-1,-1,1,1,1], "functions": {"b": "x^2+y^2+z^2-1"}})", "limits.json"));
}

TEST(DomainFileLimits, RunawayAndDuplicateCurvesAreRefused) {
  const std::string head = R"({"bbox": [-0.8,-0.8,-0.9,0.8,0.8,0.9],
    "functions": {"side": "x^2+y^2-0.25", "top": "z-0.6", "bottom": "-z-0.6"},
    "subdomains": [{"inside": ["side", "top", "bottom"]}], "curves": [)";
  const std::string circle = R"j("x": "0.5*cos(t)", "y": "0.5*sin(t)", "z": "0.6", "t": [0, )j";
  expect_refused(head + R"({"name": "r", )" + circle + "6283185.307179586]}]}",
                 "curve 'r': it turns at least");
  expect_refused(head + R"({"name": "r", "x": "t", "y": "0", "z": "0.6", "t": [0, 1e6]}]})",
                 "more than 1000 box diagonals");
  expect_refused(head + R"({"name": "twice", )" + circle + "12.566370614359172]}]}",
                 "curve 'twice': it runs over itself (64 of 64 points");
  expect_refused(head + R"({"name": "and_a_half", )" + circle + "9.42477796076938]}]}",
                 "curve 'and_a_half': it runs over itself");
  expect_refused(head + R"({"name": "a", )" + circle + R"(6.283185307179586]}, {"name": "b", )" +
                     circle + "6.283185307179586]}]}",
                 "curves 'a' and 'b' are the same curve");
}

}  // namespace
}  // namespace rdmesh
