// Tests of the .json domain file: samples, success cases and every error case.
#include "rdmesh/domain_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "oracles/oracle_conformance.h"
#include "rdmesh/errors.h"

namespace rdmesh {
namespace {

const std::string kSamples = std::string(RDMESH_SOURCE_DIR) + "/samples/";

/// The message of the InputError thrown by parsing `text` as "test.json".
std::string error_of(const std::string& text) {
  try {
    parse_domain_json(text, "test.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

/// Expects an error "test.json: ..." on one line containing every `parts`.
void expect_error(const std::string& text, std::initializer_list<std::string> parts) {
  const std::string message = error_of(text);
  SCOPED_TRACE(text);
  EXPECT_EQ(message.rfind("test.json: ", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  for (const std::string& part : parts) {
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
  }
}

const std::string kBox = R"("bbox": [-2, -2, -2, 2, 2, 2])";
const std::string kBall = R"("functions": {"ball": "x^2 + y^2 + z^2 - 1"})";

TEST(DomainFile, EverySampleLoadsAndConforms) {
  for (const char* name :
       {"sphere.json", "torus.json", "nested_spheres.json", "balls.json", "graded_sphere.json"}) {
    SCOPED_TRACE(name);
    LoadedDomain d = load_domain_file(kSamples + name);
    ASSERT_NE(d.oracle, nullptr);
    EXPECT_TRUE(d.hints.size.has_value());
    expect_oracle_conformance(*d.oracle, 500);
  }
}

TEST(DomainFile, SamplesHaveTheExpectedStructure) {
  LoadedDomain nested = load_domain_file(kSamples + "nested_spheres.json");
  ASSERT_EQ(nested.oracle->subdomains().size(), 2u);
  EXPECT_EQ(nested.oracle->subdomains()[0].name, "shell");
  EXPECT_EQ(nested.oracle->patches().size(), 2u);
  EXPECT_EQ(nested.oracle->locate({0, 0, 0}).label, SubdomainId(2));
  LoadedDomain balls = load_domain_file(kSamples + "balls.json");
  ASSERT_EQ(balls.oracle->patches().size(), 1u);
  EXPECT_GE(balls.oracle->initial_points(balls.oracle->patches()[0].id).size(), 9u);
  LoadedDomain graded = load_domain_file(kSamples + "graded_sphere.json");
  ASSERT_TRUE(graded.hints.size.has_value());
  EXPECT_FALSE(graded.hints.size->is_uniform());
  EXPECT_NEAR((*graded.hints.size)({1, 0, 0}), 0.2, 1e-12);
  EXPECT_NEAR((*graded.hints.size)({-1, 0, 0}), 0.04, 1e-12);
  EXPECT_EQ(graded.hints.facet_angle, 25.0);
  EXPECT_EQ(graded.hints.radius_edge, 2.0);
}

TEST(DomainFile, MinimalFileAndHints) {
  LoadedDomain d = parse_domain_json(
      "{" + kBox + ", " + kBall +
          R"(, "size": 0.2, "facet_size": "0.1 + 0*x", "cell_size": 0.3, "facet_distance": 0.01,
          // comments are allowed
          "curves": [], "description": "d"})",
      "test.json");
  EXPECT_EQ(d.oracle->locate({0, 0, 0}).label, SubdomainId(1));
  EXPECT_EQ(d.oracle->locate({1.5, 0, 0}).label, kOutside);
  EXPECT_EQ(d.oracle->subdomains()[0].name, "ball");
  ASSERT_TRUE(d.hints.size && d.hints.size->is_uniform());
  EXPECT_EQ(d.hints.size->constant, 0.2);
  EXPECT_NEAR((*d.hints.facet_size)({0.3, 0.1, 0}), 0.1, 1e-15);
  // An expression keeps one parser per thread: it may be evaluated from several.
  EXPECT_FALSE(d.hints.facet_size->is_uniform());
  EXPECT_TRUE(d.hints.facet_size->is_concurrent());
  EXPECT_EQ(d.hints.cell_size->constant, 0.3);
  EXPECT_EQ(d.hints.facet_distance, 0.01);
  EXPECT_FALSE(d.hints.facet_angle.has_value());
  EXPECT_FALSE(d.hints.radius_edge.has_value());
}

TEST(DomainFile, SizesObjectAsASizingFileWritesIt) {
  const LoadedDomain d = parse_domain_json(
      "{" + kBox + ", " + kBall +
          R"(, "sizes": {"patch:1": 0.05, "subdomain:ball": 0.1, "grade": 1.3, "curvature": 12}})",
      "test.json");
  ASSERT_TRUE(d.hints.sizes.has_value());
  ASSERT_EQ(d.hints.sizes->entities.size(), 2u);
  EXPECT_EQ(d.hints.sizes->entities[0].first, "patch:1");
  EXPECT_EQ(d.hints.sizes->entities[1].second, 0.1);
  EXPECT_EQ(d.hints.sizes->grade, 1.3);
  EXPECT_EQ(d.hints.sizes->curvature, 12);
  EXPECT_FALSE(parse_domain_json("{" + kBox + ", " + kBall + "}", "t").hints.sizes.has_value());
  expect_error("{" + kBox + ", " + kBall + R"(, "sizes": {"curvature": -3}})",
               {"test.json: 'sizes': ", "'curvature' must be a positive number"});
  expect_error("{" + kBox + ", " + kBall + R"(, "sizes": {"patch1": 0.1}})",
               {"'sizes': unknown key 'patch1'"});
  expect_error("{" + kBox + ", " + kBall + R"(, "sizes": 0.1})", {"'sizes': expected an object"});
}

TEST(DomainFile, SubdomainsWithOutsideAndSingleNames) {
  LoadedDomain d = parse_domain_json("{" + kBox + R"(, "functions": {
      "ball": "x^2 + y^2 + z^2 - 1", "hole": "x^2 + y^2 - 0.09"},
      "subdomains": [{"name": "shell", "inside": "ball", "outside": ["hole"]},
                     {"inside": ["hole", "ball"]}]})",
                                     "test.json");
  EXPECT_EQ(d.oracle->locate({0.6, 0, 0}).label, SubdomainId(1));
  EXPECT_EQ(d.oracle->locate({0, 0, 0.5}).label, SubdomainId(2));
  EXPECT_EQ(d.oracle->locate({0, 0, 1.5}).label, kOutside);
  EXPECT_EQ(d.oracle->subdomains()[1].name, "subdomain_2");
  expect_oracle_conformance(*d.oracle, 1000);
}

TEST(DomainFile, FileErrors) {
  const std::string missing = kSamples + "does_not_exist.json";
  try {
    load_domain_file(missing);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": no such file");
  }
  try {
    load_domain_file(kSamples);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("directory"), std::string::npos);
  }
  const std::string path = testing::TempDir() + "rdmesh_unreadable.json";
  std::ofstream(path) << "{";
  std::filesystem::permissions(path, std::filesystem::perms::none);
  std::ifstream probe(path);
  if (!probe) {  // root can read anything: skip then
    try {
      load_domain_file(path);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path + ": cannot open file"), std::string::npos);
    }
  }
  std::filesystem::permissions(path, std::filesystem::perms::owner_all);
  try {
    load_domain_file(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": malformed JSON"), std::string::npos);
  }
  std::filesystem::remove(path);
}

TEST(DomainFile, JsonErrors) {
  expect_error("{\n  \"bbox\": [1, 2,\n}", {"malformed JSON", "line 3, column 1"});
  expect_error("", {"malformed JSON"});
  expect_error("[1, 2]", {"top level must be a JSON object"});
  expect_error("{" + kBox + ", " + kBall + R"(, "sise": 0.1})",
               {"unknown key 'sise'", "top level"});
  expect_error("{" + kBox + ", " + kBall + R"(, "description": 3})", {"'description'"});
}

TEST(DomainFile, BoxErrors) {
  expect_error("{" + kBall + "}", {"missing 'bbox'"});
  expect_error(R"({"bbox": [0, 0, 0, 1, 1], )" + kBall + "}", {"'bbox' must be an array of 6"});
  expect_error(R"({"bbox": [0, 0, "a", 1, 1, 1], )" + kBall + "}", {"'bbox' entry 2"});
  expect_error(R"({"bbox": [-2, 1, -2, 2, 0, 2], )" + kBall + "}",
               {"'bbox' is empty along y", "ymin 1 >= ymax 0"});
  expect_error(R"({"bbox": [-2, -2, 1, 2, 2, 1], )" + kBall + "}", {"empty along z"});
}

TEST(DomainFile, FunctionErrors) {
  expect_error("{" + kBox + "}", {"missing 'functions'"});
  expect_error("{" + kBox + R"(, "functions": {}})", {"'functions' must be a non-empty object"});
  expect_error("{" + kBox + R"(, "functions": {"ball": 1}})",
               {"function 'ball' must be an expression string"});
  expect_error("{" + kBox + R"(, "functions": {"ball": "x^2 + y^2 + *z - 1"}})",
               {"function 'ball'", "syntax error in 'x^2 + y^2 + *z - 1'"});
  expect_error("{" + kBox + R"(, "functions": {"ball": "x^2 + w^2 - 1"}})",
               {"function 'ball'", "unknown variable 'w'"});
  expect_error("{" + kBox + R"(, "functions": {"ball": "sqr(x) - 1"}})",
               {"function 'ball'", "unknown function 'sqr'"});
  expect_error("{" + kBox + R"(, "functions": {"ball": "  "}})", {"function 'ball'", "empty"});
  expect_error("{" + kBox + ", " + kBall + R"(, "curves": [{"name": "rim"}]})",
               {"curve 'rim': give either"});
}

TEST(DomainFile, SubdomainErrors) {
  const std::string two =
      R"("functions": {"ball": "x^2 + y^2 + z^2 - 1", "hole": "x^2 + y^2 - 0.09"})";
  expect_error("{" + kBox + ", " + two + "}", {"'subdomains' is required", "2 given"});
  expect_error("{" + kBox + ", " + two + R"(, "subdomains": []})", {"non-empty list"});
  expect_error("{" + kBox + ", " + two + R"(, "subdomains": [{"name": "s", "inside": ["bal"]}]})",
               {"subdomain 's'", "unknown function 'bal'", "'inside'", "ball, hole"});
  expect_error("{" + kBox + ", " + two + R"(, "subdomains": [{"inside": ["ball"], "outsid": []}]})",
               {"unknown key 'outsid'", "subdomain 'subdomain_1'"});
  expect_error("{" + kBox + ", " + two + R"(, "subdomains": [{"inside": [1]}]})",
               {"list of function names"});
  expect_error("{" + kBox + ", " + two + R"(, "subdomains": [{"name": "e"}]})",
               {"subdomain 'e' has neither inside nor outside"});
  expect_error(
      "{" + kBox + ", " + two +
          R"(, "subdomains": [{"name": "void", "inside": ["hole"], "outside": ["hole"]}]})",
      {"subdomain 'void' matches no point of the box"});
  expect_error(R"({"bbox": [5, 5, 5, 6, 6, 6], )" + kBall + "}",
               {"subdomain 'ball' matches no point of the box"});
}

TEST(DomainFile, CriteriaErrors) {
  const std::string head = "{" + kBox + ", " + kBall + ", ";
  expect_error(head + R"("size": 0})", {"'size' must be a positive finite number", "got 0"});
  expect_error(head + R"("size": -0.5})", {"'size'", "got -0.5"});
  expect_error(head + R"("size": 1e999})", {"number overflow", "1e999"});
  expect_error(head + R"("facet_size": true})", {"'facet_size' must be a number or an expression"});
  expect_error(head + R"("cell_size": "x - 1"})",
               {"'cell_size' expression 'x - 1' evaluates to -1 at the box center (0, 0, 0)"});
  expect_error(head + R"j("size": "sqrt(x - 1)"})j", {"'size'", "nan"});
  expect_error(head + R"("size": "0.1 + q"})", {"'size'", "unknown variable 'q'"});
  expect_error(head + R"("facet_distance": 0})", {"'facet_distance' must be a positive"});
  expect_error(head + R"("facet_distance": "0.1"})", {"'facet_distance' must be a number"});
  expect_error(head + R"("facet_angle": 75})", {"'facet_angle'", "below 60", "got 75"});
  expect_error(head + R"("radius_edge": -2})", {"'radius_edge'", "got -2"});
}

}  // namespace
}  // namespace rdmesh
