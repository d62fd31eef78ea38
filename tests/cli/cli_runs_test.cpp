// Successful runs: every bundled sample meshes, every output format is
// written, the report and the summary carry the figures of the mesh.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace rdmesh::test {
namespace {

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

class CliSample : public ::testing::TestWithParam<const char*> {};

TEST_P(CliSample, MeshesWithDefaultsAndReportsAClosedBoundary) {
  ScratchDir dir;
  const std::string sample = source_path(std::string("samples/") + GetParam() + ".json");
  const CliRun run = run_cli("'" + sample + "' -o out.mesh --quiet --report r.json", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(run.output.empty()) << "--quiet printed: " << run.output;
  ASSERT_TRUE(std::filesystem::exists(dir.file("out.mesh")));
  const nlohmann::json r = read_json(dir.file("r.json"));
  EXPECT_GT(r.at("tets").get<int>(), 100);
  EXPECT_FALSE(r.at("guard").at("fired").get<bool>());
  // Every patch is a closed surface here (spheres: 2 per component, torus: 0).
  // The facet distance (R4) is measured at a facet's circumcenter; the report
  // samples edge midpoints too, and an edge along the torus's tube (radius 0.3)
  // of length 0.14 bulges 0.0083 at its midpoint while the circumcenters of
  // both its facets stay within 0.0035: twice the criterion bounds both.
  for (const auto& patch : r.at("patches")) {
    EXPECT_GT(patch.at("triangles").get<int>(), 0);
    EXPECT_LE(patch.at("max_distance").get<double>(),
              r.at("criteria").at("facet_distance").get<double>() * 2);
  }
  double volume = 0;
  for (const auto& sub : r.at("subdomains")) volume += sub.at("volume").get<double>();
  EXPECT_GT(volume, 0);
  EXPECT_GT(r.at("seconds").at("refine").get<double>(), 0);
}

INSTANTIATE_TEST_SUITE_P(Samples, CliSample,
                         ::testing::Values("sphere", "torus", "nested_spheres", "balls",
                                           "graded_sphere"));

TEST(CliRun, WritesEveryFormatAndDefaultOutputName) {
  ScratchDir dir;
  const std::string sample = "'" + source_path("samples/sphere.json") + "'";
  for (const char* name : {"a.mesh", "b.msh", "c.vtu"}) {
    const CliRun run = run_cli(sample + " -o " + name + " --quiet --size 0.3", dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_GT(std::filesystem::file_size(dir.file(name)), 1000u) << name;
  }
  const CliRun run = run_cli(sample + " --size 0.3", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(std::filesystem::exists(dir.file("sphere.msh")));
  EXPECT_NE(run.output.find("Euler characteristic 2"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("guard: not fired"), std::string::npos) << run.output;
  EXPECT_EQ(dir.entries(), 4u) << "temporary files left behind";
}

TEST(CliRun, OptionsOverrideTheFileAndSizeChangesTheMesh) {
  ScratchDir dir;
  const std::string sample = "'" + source_path("samples/sphere.json") + "'";
  ASSERT_EQ(run_cli(sample + " -o a.mesh -q --size 0.3 --report a.json", dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli(sample + " -o b.mesh -q --size 0.15 --report b.json", dir.path()).exit_code, 0);
  const nlohmann::json a = read_json(dir.file("a.json")), b = read_json(dir.file("b.json"));
  EXPECT_DOUBLE_EQ(a.at("criteria").at("facet_size").get<double>(), 0.3);
  EXPECT_DOUBLE_EQ(a.at("criteria").at("facet_distance").get<double>(), 0.03);
  EXPECT_GT(b.at("tets").get<int>(), 4 * a.at("tets").get<int>());
}

}  // namespace
}  // namespace rdmesh::test
