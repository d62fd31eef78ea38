// Hostile input and absurd criteria (issue 23): each is refused up front with exit
// code 2 and one line naming the file, after well under a CPU-second, leaving no file.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "shared_data.h"

namespace rdmesh::test {
namespace {

const std::string kBall = R"("functions": {"s": "x^2+y^2+z^2-1"})";
const std::string kSphere = R"({"bbox": [-1.2,-1.2,-1.2,1.2,1.2,1.2], )" + kBall + "}";

/// A domain file with the sphere's box and `functions`, plus `rest` (", ..." or "").
std::string domain(const std::string& functions, const std::string& rest = "") {
  return R"({"bbox": [-1,-1,-1,1,1,1], "functions": {"s": ")" + functions + "\"}" + rest + "}";
}

/// capped_cylinder.json's domain with `curves` (a JSON list).
std::string cylinder_with(const std::string& curves) {
  return R"({"bbox": [-0.8,-0.8,-0.9,0.8,0.8,0.9],
    "functions": {"side": "x^2+y^2-0.25", "top": "z-0.6", "bottom": "-z-0.6"},
    "subdomains": [{"name": "c", "inside": ["side", "top", "bottom"]}], "curves": )" +
         curves + "}";
}

std::string rim(const std::string& name, double turns) {
  return R"({"name": ")" + name +
         R"j(", "x": "0.5*cos(t)", "y": "0.5*sin(t)", "z": "0.6", "t": [0, )j" +
         std::to_string(turns * 6.283185307179586) + "]}";
}

struct Refused {
  std::string name;
  std::string input;     ///< file name in the scratch directory
  std::string text;      ///< its content
  std::string args;      ///< after "INPUT -q -o out.msh"
  std::string expected;  ///< substring of the message
};

/// Runs `input args` in `dir` and checks the refusal contract: the line starts with
/// "rdmesh: error: SHOWN: " (SHOWN: the input's name as printed, default `input`) and
/// contains `expected`; `files` is the number of entries the directory must still hold.
void expect_refused(const ScratchDir& dir, const std::string& input, const std::string& args,
                    const std::string& expected, std::size_t files, std::string shown = "") {
  if (shown.empty()) shown = input;
  // CPU seconds of the run (its shell and rdmesh, both waited for): the work the
  // refusal took, which a loaded machine does not stretch the way it stretches wall time.
  const double before = children_cpu_seconds();
  const CliRun run = run_cli("'" + input + "' -q " + args, dir.path());
  const double seconds = children_cpu_seconds() - before;
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
  EXPECT_EQ(run.output.rfind("rdmesh: error: " + shown + ": ", 0), 0u) << run.output;
  EXPECT_NE(run.output.find(expected), std::string::npos)
      << "message lacks '" << expected << "': " << run.output;
  EXPECT_LT(seconds, 2.0) << "refused after too much work: " << run.output;  // ~0.1 s measured
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.msh")));
  EXPECT_EQ(dir.entries(), files) << "a stray file was left behind";
}

class CliLimits : public ::testing::TestWithParam<Refused> {};

TEST_P(CliLimits, RefusedUpFrontWithOneLine) {
  const Refused& c = GetParam();
  ScratchDir dir;
  dir.write(c.input, c.text);
  expect_refused(dir, c.input, "-o out.msh " + c.args, c.expected, 1);
}

std::vector<Refused> cases() {
  std::string deep = R"({"bbox": )" + std::string(200000, '[') + std::string(200000, ']') + "}";
  std::string fifty = "[";
  for (int i = 0; i < 50; ++i) {
    if (i > 0) fifty += ", ";
    fifty += rim(std::string("c").append(std::to_string(i)), 1);
  }
  fifty += "]";
  std::string twice = "[";
  twice.append(rim("rim", 2)).append("]");
  std::string long_sum = "x";  // appends: GCC 12 warns (-Wrestrict) on "literal" + string
  long_sum.append(20000, '+').append("1");
  std::string one_rim = "[";
  one_rim.append(rim("rim", 1e6)).append("]");
  const std::string ply_head = "ply\nformat ascii 1.0\n";
  return {
      // Criteria without a termination proof, or that imply an absurd mesh.
      {"radius_edge_below_2", "in.json", kSphere, "--radius-edge 1.5", "below 2"},
      {"facet_angle_above_30", "in.json", kSphere, "--facet-angle 45", "(0, 30]"},
      {"size_below_min_size", "in.json", kSphere, "--size 1e-9", "below the minimum size"},
      {"facet_distance_below_min_size", "in.json", kSphere, "--facet-distance 1e-12",
       "facet distance 1e-12 is below the minimum size"},
      {"file_facet_distance_tiny", "in.json",
       R"({"bbox": [-1.2,-1.2,-1.2,1.2,1.2,1.2], )" + kBall + R"(, "facet_distance": 1e-300})", "",
       "facet distance 1e-300"},
      {"size_expression_negative_somewhere", "in.json",
       R"({"bbox": [-1.2,-1.2,-1.2,1.2,1.2,1.2], )" + kBall + R"(, "size": "0.3 - x"})", "",
       "edge size is -0.1 at (0.4, -1.2, -1.2)"},
      {"too_many_elements", "in.json", kSphere, "--size 0.005",
       "above the limit of 5e+07: coarsen the sizes, or raise the limit with --max-elements"},
      {"lowered_element_limit", "in.json", kSphere, "--max-elements 1000", "limit of 1000"},
      // Degenerate implicit domains.
      {"domain_fills_box", "in.json", domain("-1"), "", "the domain reaches the bounding box"},
      {"half_space_sign", "in.json", domain("sign(x)"), "", "reaches the bounding box"},
      {"denormal_function", "in.json", domain("1e-320*x"), "", "reaches the bounding box"},
      {"ball_larger_than_box", "in.json", domain("x^2+y^2+z^2-1.2"), "",
       "reaches the bounding box"},
      {"nan_everywhere", "in.json", domain("sqrt(-1-x^2)"), "", "matches no point"},
      {"empty_domain", "in.json", domain("x^2+y^2+z^2+1"), "", "matches no point"},
      {"tiny_box", "in.json",
       R"({"bbox": [-1e-12,-1e-12,-1e-12,1e-12,1e-12,1e-12], "functions": {"s": "x^2+y^2+z^2-1e-25"}})",
       "", "'bbox' extent along x 2e-12 is below 1e-6"},
      {"nesting_bomb", "in.json", deep, "", "nested deeper than 64"},
      {"long_expression", "in.json", domain(long_sum), "", "at most 10000"},
      {"million_turns", "in.json", cylinder_with(one_rim), "", "curve 'rim': it turns at least"},
      {"circle_traversed_twice", "in.json", cylinder_with(twice), "", "runs over itself"},
      {"fifty_identical_curves", "in.json", cylinder_with(fifty), "",
       "curves 'c0' and 'c1' are the same curve"},
      {"constant_curve", "in.json",
       cylinder_with(R"([{"name": "dot", "x": "0.5", "y": "0", "z": "0.6", "t": [0, 1]}])"), "",
       "curve 'dot': it is a point, not a curve"},
      {"curve_range_below_resolution", "in.json",
       cylinder_with(
           R"j([{"name": "dot", "x": "0.5*cos(t)", "y": "0.5*sin(t)", "z": "0.6", "t": [0, 1e-300]}])j"),
       "", "curve 'dot': it is a point, not a curve"},
      // A coordinate near the largest double (a campaign mutant of cube.json).
      {"curve_at_largest_double", "in.json",
       cylinder_with(R"([{"name": "far", "x": "1e308", "y": "t", "z": "0.6", "t": [0, 1]}])"), "",
       "curve 'far': its arc length is not finite: coordinates up to 1e+308"},
      // PLY headers that the file cannot hold.
      {"ply_element_without_properties", "in.ply",
       ply_head + "element junk 9000000000000000000\nend_header\n", "", "no property"},
      {"ply_huge_vertex_count", "in.ply",
       ply_head + "element vertex 1000000000000\nproperty float x\nproperty float y\n"
                  "property float z\nend_header\n0 0 0\n",
       "", "ends early"},
  };
}

INSTANTIATE_TEST_SUITE_P(Cases, CliLimits, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Refused>& info) {
                           return info.param.name;
                         });

TEST(CliLimits, ADomainThinnerThanItsCellsIsAnInputErrorNotAnInternalOne) {
  // A closed tetrahedron 0.016 thick in a box of 2.2 (a mutant of
  // cgal_wedge.off found by fuzz/cli_campaign.py): no cell's centre lies
  // inside it (nor at 0.01: its faces meet at about a degree). It was exit 3.
  ScratchDir dir;
  const std::string off = dir.write("thin.off",
                                    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n"
                                    "0.0032586249615044064 -1 -0.016375682947558277\n"
                                    "3 0 1 2\n3 2 1 3\n3 0 2 3\n3 1 0 3\n");
  const CliRun run = run_cli("thin.off -o thin.mesh -q", dir.path());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_EQ(run.output.rfind("rdmesh: error: thin.off: no tetrahedron has its centre inside", 0),
            0u)
      << run.output;
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("thin.mesh")));
}

TEST(CliLimits, ASizeWhoseBallsHoldEveryPatchPointIsAnInputErrorNotAnInternalOne) {
  // The lens sample at --size 4294967295 (a mutant found by
  // fuzz/cli_campaign.py; from --size 5 on): three protecting balls on its rim
  // hold every initial point of both caps, and the rim's three centres span
  // no volume. It was exit 3 without the file's name.
  ScratchDir dir;
  for (const char* size : {"5", "4294967295"}) {
    const CliRun run = run_cli(
        source_path("samples/lens.json") + " --size " + size + " -o lens.mesh -q", dir.path());
    EXPECT_EQ(run.exit_code, 2) << size << ": " << run.output;
    EXPECT_NE(run.output.find("lens.json: the sizes are too large for this domain: the "
                              "protecting balls of the curves hold"),
              std::string::npos)
        << run.output;
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    EXPECT_FALSE(std::filesystem::exists(dir.file("lens.mesh")));
  }
  // At --size 3 the balls leave room: a mesh.
  const CliRun ok =
      run_cli(source_path("samples/lens.json") + " --size 3 -o lens.mesh -q", dir.path());
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

TEST(CliLimits, TheTimeLimitAlsoStopsProtectionAndTheInitialPoints) {
  // A tetrahedron 4e9 long and 0.016 thick (a mutant of cgal_wedge.off found
  // by fuzz/cli_campaign.py): its edges are protected down to the minimum
  // size, 9 s of ball planning and 7 s of inserting them on a 2-core machine,
  // and --time-limit 10 bounded only refinement. Now the limit stops any phase:
  // exit 4, one line, no mesh.
  ScratchDir dir;
  dir.write("needle.off",
            "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n"
            "4294967295 -0.0014027867165072405 -0.016375682947558277\n"
            "3 0 1 2\n3 2 1 3\n3 0 2 3\n3 1 0 3\n");
  const CliRun run =
      run_cli("needle.off -o needle.mesh -q --time-limit 0.2 --report r.json", dir.path());
  EXPECT_EQ(run.exit_code, 4) << run.output;
  EXPECT_NE(run.output.find("rdmesh: error: needle.off: the time limit (0.2 s) stopped the run"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("needle.mesh")));
  const nlohmann::json report = nlohmann::json::parse(read_file(dir.file("r.json")));
  EXPECT_TRUE(report["refinement"]["time_limit_reached"].get<bool>());
  const std::string phase = report["refinement"]["stopped_in"].get<std::string>();
  EXPECT_TRUE(phase == "protection" || phase == "initial points") << phase;
  EXPECT_NE(report["failure"].get<std::string>().find("the time limit (0.2 s) stopped the run"),
            std::string::npos)
      << report["failure"];
}

TEST(CliLimits, SharedJunkPlyIsRefused) {
  RDMESH_REQUIRE_SHARED_DATA(junk, "bad/junk.ply");
  ScratchDir dir;
  expect_refused(dir, junk, "-o out.msh", "PLY element 'junk'", 0);
}

TEST(CliLimits, DirectoryFifoAndMissingInputsAreNamedTheSameForEveryKind) {
  ScratchDir dir;
  for (const char* ext : {".json", ".step", ".stl", ".off", ".ply"}) {
    const std::string name = std::string("in") + ext;
    expect_refused(dir, name, "-o out.msh", "no such file", 0);
    std::filesystem::create_directory(dir.file(name));
    expect_refused(dir, name, "-o out.msh", "is a directory", 1);
    std::filesystem::remove(dir.file(name));
    ASSERT_EQ(::mkfifo(dir.file(name).c_str(), 0600), 0);
    expect_refused(dir, name, "-o out.msh", "not a regular file", 1);
    std::filesystem::remove(dir.file(name));
  }
}

TEST(CliLimits, ControlCharactersInTheFileNameKeepTheMessageOnOneLine) {
  ScratchDir dir;
  expect_refused(dir, "a\nb\x01.json", "-o out.msh", "no such file", 0, "a\\nb\\x01.json");
}

TEST(CliLimits, AnOutputThatIsTheInputOrAnotherOutputIsRefused) {
  ScratchDir dir;
  dir.write("in.json", kSphere);
  expect_refused(dir, "in.json", "-o out.msh --report in.json", "--report in.json is the input", 1);
  expect_refused(dir, "in.json", "-o ./in.json", "-o ./in.json is the input", 1);
  expect_refused(dir, "in.json",
                 "-o out.msh --picture ../" + dir.path().filename().string() + "/in.json",
                 "is the input", 1);
  expect_refused(dir, "in.json", "-o out.msh --report out.msh", "is also the -o output", 1);
  std::ifstream in(dir.file("in.json"));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, kSphere) << "the input was overwritten";
}

TEST(CliLimits, ParseErrorsNameTheOption) {
  ScratchDir dir;
  dir.write("in.json", kSphere);
  expect_refused(dir, "in.json", "-o out.msh --size abc", "--size", 1);
  expect_refused(dir, "in.json", "-o out.msh --max-elements -5", "--max-elements", 1);
}

TEST(CliLimits, ReportShowsTheMinimumSizeUsed) {
  ScratchDir dir;
  dir.write("in.json", kSphere);
  const CliRun run =
      run_cli("in.json -q --size 0.4 --no-exude -o out.msh --report r.json", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::ifstream in(dir.file("r.json"));
  const nlohmann::json report = nlohmann::json::parse(in);
  const double diagonal = 2.4 * std::sqrt(3.0);
  EXPECT_NEAR(report.at("criteria").at("min_size").get<double>(), 1e-4 * diagonal, 1e-12);
}

}  // namespace
}  // namespace rdmesh::test
