// Output bytes depend on the input and the options only (issue 23 item 7): two runs
// on the same input give the same mesh file, for each kind of input.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "cli_runner.h"
#include "shared_data.h"

namespace rdmesh::test {
namespace {

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Meshes `input` twice with `args` and compares the two .msh files byte for byte.
void expect_same_bytes_twice(const std::string& input, const std::string& args) {
  ScratchDir dir;
  for (const char* out : {"a.msh", "b.msh"}) {
    const CliRun run = run_cli("'" + input + "' -q " + args + " -o " + out, dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.output;
  }
  const std::string a = bytes_of(dir.file("a.msh")), b = bytes_of(dir.file("b.msh"));
  EXPECT_GT(a.size(), 1000u);
  EXPECT_TRUE(a == b) << input << ": two runs wrote different bytes (" << a.size() << " and "
                      << b.size() << ")";
}

TEST(CliDeterminism, ImplicitDomain) {
  expect_same_bytes_twice(source_path("samples/capped_cylinder.json"), "--size 0.2");
}

TEST(CliDeterminism, TriangleMesh) {
  RDMESH_REQUIRE_SHARED_DATA(part, "mesh/cgal_part.off");
  expect_same_bytes_twice(part, "");
}

TEST(CliDeterminism, StepPart) {
  expect_same_bytes_twice(source_path("samples/plate_with_hole.step"), "");
}

}  // namespace
}  // namespace rdmesh::test
