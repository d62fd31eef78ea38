// --version, and what the JSON report says about the run itself: the version,
// the command line, the input's SHA-256 and every criterion as used.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "cli_runner.h"

namespace rdmesh::test {
namespace {

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

/// What `sha256sum FILE` prints first: the file's digest.
std::string sha256sum(const std::string& path) {
  FILE* pipe = ::popen(("sha256sum '" + path + "'").c_str(), "r");
  std::array<char, 65> digest{};
  const std::size_t n = pipe ? std::fread(digest.data(), 1, 64, pipe) : 0;
  if (pipe) ::pclose(pipe);
  return std::string(digest.data(), n);
}

TEST(CliVersion, PrintsTheProjectVersionAndExitsZero) {
  ScratchDir dir;
  const CliRun run = run_cli("--version", dir.path());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(std::regex_match(run.output, std::regex("rdmesh [0-9]+\\.[0-9]+\\.[0-9]+\n")))
      << run.output;
  EXPECT_EQ(dir.entries(), 0u);
}

TEST(CliReport, CarriesVersionCommandLineChecksumAndTheCriteriaUsed) {
  ScratchDir dir;
  const std::string sample = source_path("samples/sphere.json");
  const std::string args = "'" + sample + "' -o out.msh --size 0.4 --report r.json -q";
  const CliRun run = run_cli(args, dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json r = read_json(dir.file("r.json"));
  const CliRun version = run_cli("--version", dir.path());
  EXPECT_EQ("rdmesh " + r.at("rdmesh_version").get<std::string>() + "\n", version.output);
  const std::string command_line = r.at("command_line").get<std::string>();
  EXPECT_NE(command_line.find(sample + " -o out.msh --size 0.4 --report r.json -q"),
            std::string::npos)
      << command_line;
  EXPECT_EQ(r.at("input_sha256").get<std::string>(), sha256sum(sample));
  EXPECT_EQ(r.at("input_sha256").get<std::string>().size(), 64u);

  const nlohmann::json& c = r.at("criteria");
  EXPECT_EQ(c.at("cell_size").get<double>(), 0.4);
  EXPECT_EQ(c.at("facet_size").get<double>(), 0.4);
  EXPECT_EQ(c.at("edge_size").get<double>(), 0.4);
  EXPECT_DOUBLE_EQ(c.at("facet_distance").get<double>(), 0.04);
  EXPECT_EQ(c.at("facet_angle_deg").get<double>(), 25);
  EXPECT_EQ(c.at("cell_radius_edge").get<double>(), 2);
  // The minimum size as used: 1e-4 of the box's diagonal (sphere.json: 2.4 wide).
  EXPECT_NEAR(c.at("min_size").get<double>(), 1e-4 * 2.4 * std::sqrt(3.0), 1e-12);
  EXPECT_EQ(c.at("max_elements").get<double>(), 5e7);
  EXPECT_EQ(c.at("features").get<std::string>(), "protect");
  EXPECT_EQ(c.at("check").get<std::string>(), "full");
  EXPECT_TRUE(c.at("exudation").get<bool>());
  EXPECT_EQ(c.at("exude_bound_deg").get<double>(), 25);
  EXPECT_FALSE(c.at("surface_only").get<bool>());
  EXPECT_FALSE(c.contains("feature_angle_deg")) << "not a triangle mesh";
}

TEST(CliReport, AVaryingSizeShowsItsRangeAndGivenOptionsWin) {
  ScratchDir dir;
  const std::string sample = source_path("samples/graded_sphere.json");
  const CliRun run = run_cli(std::string("'") + sample +
                                 "' -o out.msh --report r.json -q --min-size 0.002 "
                                 "--features refine --facet-angle 20 --exude-time-limit 7",
                             dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json c = read_json(dir.file("r.json")).at("criteria");
  const nlohmann::json& cell = c.at("cell_size");
  ASSERT_TRUE(cell.is_object()) << cell;
  EXPECT_TRUE(cell.at("varying").get<bool>());
  EXPECT_LT(cell.at("min").get<double>(), cell.at("max").get<double>());
  EXPECT_GT(cell.at("min").get<double>(), 0);
  EXPECT_EQ(c.at("min_size").get<double>(), 0.002);
  EXPECT_EQ(c.at("features").get<std::string>(), "refine");
  EXPECT_EQ(c.at("facet_angle_deg").get<double>(), 20);
  EXPECT_EQ(c.at("exude_time_limit_s").get<double>(), 7);
}

TEST(CliReport, TheExudationBoundDecidesWhichVerticesArePumped) {
  // A lower bound pumps fewer vertices (only those of tets below it), and the
  // final improvement still lifts every tet to 20 degrees.
  ScratchDir dir;
  const std::string sample = source_path("samples/sphere.json");
  auto exudation = [&](const std::string& extra, const std::string& report) {
    const CliRun run =
        run_cli("'" + sample + "' -o out.msh --size 0.1 -q --report " + report + extra, dir.path());
    EXPECT_EQ(run.exit_code, 0) << run.output;
    return read_json(dir.file(report));
  };
  const nlohmann::json wide = exudation("", "wide.json");
  const nlohmann::json narrow = exudation(" --exude-bound 10", "narrow.json");
  EXPECT_EQ(narrow.at("criteria").at("exude_bound_deg").get<double>(), 10);
  const std::size_t wide_tries = wide.at("exudation").at("moves_tried").get<std::size_t>();
  const std::size_t narrow_tries = narrow.at("exudation").at("moves_tried").get<std::size_t>();
  EXPECT_GT(narrow_tries, 0u);
  EXPECT_LT(2 * narrow_tries, wide_tries);
  for (const nlohmann::json* r : {&wide, &narrow})
    EXPECT_GE(r->at("optimization").at("min_dihedral_after_deg").get<double>(), 20.0 - 1e-9);
}

}  // namespace
}  // namespace rdmesh::test
