// Inputs other than implicit domains through the CLI: triangle meshes and CAD.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "shared_data.h"

namespace rdmesh::test {
namespace {

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(CliInputs, TriangleMeshWithFeatureAngle) {
  ScratchDir dir;
  RDMESH_REQUIRE_SHARED_DATA(fandisk, "mesh/cgal_fandisk.off");
  const std::string kFandisk = "'" + fandisk + "'";
  ASSERT_EQ(run_cli(kFandisk + " -o a.mesh -q --report a.json", dir.path()).exit_code, 0);
  ASSERT_EQ(
      run_cli(kFandisk + " -o b.mesh -q --feature-angle 30 --report b.json", dir.path()).exit_code,
      0);
  const nlohmann::json a = read_json(dir.file("a.json")), b = read_json(dir.file("b.json"));
  EXPECT_GT(a.at("curves").size(), 0u);
  // A lower threshold makes more edges sharp: at least as many curves and patches.
  EXPECT_GE(b.at("curves").size(), a.at("curves").size());
  EXPECT_GE(b.at("patches").size(), a.at("patches").size());
  for (const auto& c : a.at("curves")) EXPECT_TRUE(c.at("is_chain").get<bool>()) << c.at("name");
  EXPECT_EQ(a.at("corners_present"), a.at("corners_expected"));
}

TEST(CliInputs, OpenTriangleSurfaceIsRejected) {
  ScratchDir dir;
  // One triangle: not a closed surface.
  dir.write("open.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const CliRun run = run_cli("open.off -o out.msh", dir.path());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("open.off"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("--surface-only"), std::string::npos) << "the error names the way out";
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.msh")));
}

TEST(CliInputs, SurfaceOnlyMeshesAnOpenSurface) {
  ScratchDir dir;
  // A unit square in two triangles, open along its four sides.
  dir.write("square.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  const CliRun run =
      run_cli("square.off --surface-only --size 0.2 -o out.mesh --report out.json", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("Surface mesh:"), std::string::npos) << run.output;
  const nlohmann::json r = read_json(dir.file("out.json"));
  EXPECT_EQ(r.at("tets"), 0);
  EXPECT_GT(r.at("triangles").get<int>(), 10);
  EXPECT_EQ(r.at("boundary_euler_characteristic"), 1) << "a disk";
  ASSERT_EQ(r.at("curves").size(), 4u) << "its four sides";
  for (const auto& c : r.at("curves")) EXPECT_TRUE(c.at("is_chain").get<bool>()) << c.at("name");
  EXPECT_EQ(r.at("corners_present"), 4);
}

TEST(CliInputs, CorruptStepFileIsRejected) {
  ScratchDir dir;
  dir.write("part.step", "ISO-10303-21;\nHEADER;\nthis is not a step file\n");
  const CliRun run = run_cli("part.step -o out.msh", dir.path());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("part.step"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.msh")));
}

}  // namespace
}  // namespace rdmesh::test
