// The command loads OpenCASCADE only for a CAD input (rdmesh/cad_layer.h): its
// CAD support is a module it loads from beside itself.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_runner.h"

namespace rdmesh::test {
namespace {

/// The dynamic loader's account of the files a run maps (LD_DEBUG=files),
/// with the run's own output, for `rdmesh ARGS` in `dir`.
CliRun run_cli_listing_files(const std::string& args, const std::filesystem::path& dir) {
  return run_command("env", "LD_DEBUG=files '" + std::string(RDMESH_CLI_PATH) + "' " + args, dir);
}

bool maps_opencascade(const CliRun& run) {
  return run.output.find("libTKernel.so") != std::string::npos;
}

TEST(CliCadModule, OnlyACadInputLoadsOpenCascade) {
  ScratchDir dir;
  const CliRun implicit = run_cli_listing_files(
      "'" + source_path("samples/sphere.json") + "' --size 0.3 -q -o s.mesh", dir.path());
  ASSERT_EQ(implicit.exit_code, 0) << implicit.output;
  EXPECT_FALSE(maps_opencascade(implicit)) << implicit.output;
  const CliRun version = run_cli_listing_files("--version", dir.path());
  ASSERT_EQ(version.exit_code, 0);
  EXPECT_FALSE(maps_opencascade(version)) << version.output;
  // The check above would pass if the loader's trace were off: a CAD run shows
  // the module, and OpenCASCADE with it.
  const CliRun cad = run_cli_listing_files(
      "'" + source_path("samples/plate_with_hole.step") + "' -q -o p.mesh", dir.path());
  ASSERT_EQ(cad.exit_code, 0) << cad.output.substr(0, 2000);
  EXPECT_NE(cad.output.find("rdmesh_cad_module.so"), std::string::npos);
  EXPECT_TRUE(maps_opencascade(cad));
  EXPECT_TRUE(std::filesystem::exists(dir.file("p.mesh")));
}

TEST(CliCadModule, WithoutItsModuleACadRunIsOneLineAndExit3) {
  ScratchDir dir;
  // A copy of the command alone in a folder: its module is not beside it.
  const std::filesystem::path alone = dir.path() / "rdmesh";
  std::filesystem::copy_file(RDMESH_CLI_PATH, alone);
  const CliRun run =
      run_command(alone.string(),
                  "'" + source_path("samples/plate_with_hole.step") + "' -o out.msh", dir.path());
  const std::string& output = run.output;
  EXPECT_EQ(run.exit_code, 3) << output;
  EXPECT_EQ(
      output.rfind("rdmesh: error: CAD support is not installed: no rdmesh_cad_module.so in ", 0),
      0u)
      << output;
  EXPECT_EQ(output.find('\n'), output.size() - 1) << output;  // one line
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.msh")));
  // The copy still meshes what needs no CAD.
  const CliRun implicit = run_command(
      alone.string(), "'" + source_path("samples/sphere.json") + "' --size 0.3 -q -o s.mesh",
      dir.path());
  EXPECT_EQ(implicit.exit_code, 0) << implicit.output;
  EXPECT_TRUE(std::filesystem::exists(dir.file("s.mesh")));
}

}  // namespace
}  // namespace rdmesh::test
