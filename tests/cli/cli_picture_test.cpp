// Pictures from the command line: --picture on a meshing run, and
// `rdmesh view MESH -o FILE.png` on existing mesh files.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>

#include "cli_runner.h"

namespace rdmesh::test {
namespace {

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

/// Width and height from a PNG's IHDR chunk; {0, 0} when it is not a PNG.
std::array<unsigned, 2> png_size(const std::string& path) {
  const std::string b = read_bytes(path);
  if (b.size() < 24 || b.compare(1, 3, "PNG") != 0 || b.compare(12, 4, "IHDR") != 0) return {0, 0};
  auto be32 = [&](std::size_t i) {
    return (unsigned(static_cast<unsigned char>(b[i])) << 24) |
           (unsigned(static_cast<unsigned char>(b[i + 1])) << 16) |
           (unsigned(static_cast<unsigned char>(b[i + 2])) << 8) |
           unsigned(static_cast<unsigned char>(b[i + 3]));
  };
  return {be32(16), be32(20)};
}

const std::string kSphere =
    std::string("'") + source_path("samples/sphere.json") + "' --size 0.4 --quiet";

TEST(CliPicture, MeshingRunWritesThePictureBesideTheMesh) {
  ScratchDir dir;
  const CliRun run =
      run_cli(kSphere + " -o m.msh --picture p.png --picture-size 640x400 --view z", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(std::filesystem::exists(dir.file("m.msh")));
  EXPECT_EQ(png_size(dir.file("p.png")), (std::array<unsigned, 2>{640, 400}));
  EXPECT_EQ(dir.entries(), 2u) << "temporary files left behind";
  const CliRun loud = run_cli(std::string("'") + source_path("samples/sphere.json") +
                                  "' --size 0.4 -o m.msh --picture p.png --picture-size 640x400",
                              dir.path());
  EXPECT_NE(loud.output.find("wrote m.msh and p.png"), std::string::npos) << loud.output;
}

TEST(CliPicture, ViewDrawsEachFormatTheSameWayEveryTime) {
  ScratchDir dir;
  for (const char* mesh : {"m.msh", "m.mesh", "m.vtu"}) {
    ASSERT_EQ(run_cli(kSphere + " -o " + mesh, dir.path()).exit_code, 0) << mesh;
    const CliRun run = run_cli(
        std::string("view ") + mesh + " -o a.png --cut z=0.1 --picture-size 500x400", dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_NE(run.output.find("a.png"), std::string::npos) << run.output;
    EXPECT_EQ(png_size(dir.file("a.png")), (std::array<unsigned, 2>{500, 400})) << mesh;
    ASSERT_EQ(
        run_cli(std::string("view ") + mesh + " -o b.png --cut z=0.1 --picture-size 500x400 -q",
                dir.path())
            .exit_code,
        0);
    EXPECT_EQ(read_bytes(dir.file("a.png")), read_bytes(dir.file("b.png"))) << mesh;
  }
  // Default output: the mesh's stem with .png, in the current directory.
  ASSERT_EQ(run_cli("view m.vtu -q", dir.path()).exit_code, 0);
  EXPECT_EQ(png_size(dir.file("m.png")), (std::array<unsigned, 2>{1600, 900}));
}

struct BadRun {
  const char* name;
  const char* args;      ///< after kSphere (meshing run) or alone (view)
  bool view;             ///< an `rdmesh view` command line
  const char* expected;  ///< substring of the one-line message
};

void PrintTo(const BadRun& c, std::ostream* os) { *os << c.name; }

class CliPictureBad : public ::testing::TestWithParam<BadRun> {};

TEST_P(CliPictureBad, ExitsTwoWithOneLineAndWritesNothing) {
  const BadRun& c = GetParam();
  ScratchDir dir;
  dir.write("bad.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n3 1 0 3\n1\n2\n");
  const CliRun run =
      run_cli(c.view ? std::string(c.args) : kSphere + " -o m.msh " + c.args, dir.path());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
  EXPECT_EQ(run.output.rfind("rdmesh: error: ", 0), 0u) << run.output;
  EXPECT_NE(run.output.find(c.expected), std::string::npos) << run.output;
  EXPECT_EQ(dir.entries(), 1u) << "an output or a temporary file was left";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliPictureBad,
    ::testing::Values(BadRun{"picture_not_png", "--picture p.jpg", false, "p.jpg"},
                      BadRun{"picture_dir_missing", "--picture nowhere/p.png", false, "nowhere"},
                      BadRun{"picture_size", "--picture p.png --picture-size 10x10", false,
                             "--picture-size"},
                      BadRun{"cut_axis", "--picture p.png --cut w=1", false, "--cut"},
                      BadRun{"view_name", "--picture p.png --view side", false, "--view"},
                      BadRun{"view_truncated", "view bad.msh -o v.png", true, "bad.msh"},
                      BadRun{"view_missing", "view absent.vtu -o v.png", true, "absent.vtu"},
                      BadRun{"view_extension", "view bad.msh -o v.jpg", true, "v.jpg"},
                      BadRun{"view_no_mesh", "view -o v.png", true, "mesh"}),
    [](const ::testing::TestParamInfo<BadRun>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace rdmesh::test
