// The output options: --binary / --ascii and --format msh22 choose what is
// written; impossible combinations are refused before meshing.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "cli_runner.h"

namespace rdmesh::test {
namespace {

std::string sphere() {
  return std::string("'") + source_path("samples/sphere.json") + "' --size 0.5 -q";
}

TEST(CliOutputs, BinaryAsciiAndMsh22AreWrittenAsAsked) {
  ScratchDir dir;
  ASSERT_EQ(run_cli(sphere() + " -o a.msh", dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli(sphere() + " -o b.msh --binary", dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli(sphere() + " -o c.msh --format msh22", dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli(sphere() + " -o d.vtu --binary", dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli(sphere() + " -o e.vtu --ascii", dir.path()).exit_code, 0);
  EXPECT_EQ(read_file(dir.file("a.msh")).substr(0, 20), "$MeshFormat\n4.1 0 8\n");
  EXPECT_EQ(read_file(dir.file("b.msh")).substr(0, 20), "$MeshFormat\n4.1 1 8\n");
  EXPECT_EQ(read_file(dir.file("c.msh")).substr(0, 20), "$MeshFormat\n2.2 0 8\n");
  EXPECT_NE(read_file(dir.file("d.vtu")).find("vtkZLibDataCompressor"), std::string::npos);
  EXPECT_EQ(read_file(dir.file("e.vtu")).find("vtkZLibDataCompressor"), std::string::npos);
  // The same input gives the same bytes, binary too.
  ASSERT_EQ(run_cli(sphere() + " -o b2.msh --binary", dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli(sphere() + " -o d2.vtu --binary", dir.path()).exit_code, 0);
  EXPECT_EQ(read_file(dir.file("b.msh")), read_file(dir.file("b2.msh")));
  EXPECT_EQ(read_file(dir.file("d.vtu")), read_file(dir.file("d2.vtu")));
  // rdmesh view draws the compressed .vtu.
  const CliRun view = run_cli("view d.vtu -o d.png -q", dir.path());
  EXPECT_EQ(view.exit_code, 0) << view.output;
}

TEST(CliOutputs, ImpossibleCombinationsAreRefusedUpFront) {
  const std::pair<const char*, const char*> cases[] = {
      {"-o m.mesh --binary", "m.mesh: Medit .mesh is written as text only"},
      {"-o m.msh --format msh22 --binary", "m.msh: MSH 2.2 is written as text only"},
      {"-o m.vtu --format msh22", "m.vtu: MSH 2.2 is a .msh format"},
      {"-o m.msh --format msh3", "--format: 'msh3' is not allowed; expected msh41 or msh22"},
      {"-o m.msh --binary --ascii", "excludes"},
  };
  for (const auto& [args, expected] : cases) {
    ScratchDir dir;
    const CliRun run = run_cli(sphere() + " " + args, dir.path());
    EXPECT_EQ(run.exit_code, 2) << args << ": " << run.output;
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    EXPECT_NE(run.output.find(expected), std::string::npos) << args << ": " << run.output;
    EXPECT_EQ(dir.entries(), 0u) << args;
  }
}

TEST(CliOutputs, AFailedRunWritesNothingOnTwoThreadsAndKeepBadMeshWritesIt) {
  // On two threads the mesh file is written while the mesh is checked, under
  // a temporary name: a run that fails (here the time limit stops refinement)
  // must drop it, and --keep-bad-mesh must still write it.
  std::string stopped = "'";
  stopped += source_path("samples/sphere.json");
  stopped += "' --size 0.03 -q --time-limit 0.2 --threads 2 -o s.msh";
  ScratchDir dir;
  const CliRun run = run_cli(stopped, dir.path());
  EXPECT_EQ(run.exit_code, 4) << run.output;
  EXPECT_NE(run.output.find("no mesh written"), std::string::npos) << run.output;
  EXPECT_EQ(dir.entries(), 0u);
  stopped += " --keep-bad-mesh";
  const CliRun kept = run_cli(stopped, dir.path());
  EXPECT_EQ(kept.exit_code, 4) << kept.output;
  EXPECT_NE(kept.output.find("written anyway"), std::string::npos) << kept.output;
  EXPECT_EQ(dir.entries(), 1u);
  EXPECT_EQ(read_file(dir.file("s.msh")).substr(0, 12), "$MeshFormat\n");
}

}  // namespace
}  // namespace rdmesh::test
