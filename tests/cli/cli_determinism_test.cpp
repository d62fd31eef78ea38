// Output bytes depend on the input and the options only (issue 23 item 7): two runs
// on the same input give the same mesh file, for each kind of input, and so do
// runs with 1 and 2 threads (issue 19).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
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

TEST(CliDeterminism, ImplicitSphereSameBytesWithAndWithoutGlibcFmaMath) {
  // glibc picks its math functions by CPU (FMA variants where the CPU has FMA);
  // GLIBC_TUNABLES turns those variants off, as on a CPU without FMA. The
  // sphere has no transcendental function of its own, so its mesh must not
  // depend on them (rdmesh/portable_math.h): at --size 0.05 it did, through
  // the improvement's acos (md5 750534a3 against 48ca9aa7). On a CPU without
  // FMA both runs take the same variants and this compares like with like.
  ScratchDir dir;
  const std::string input = "'" + source_path("samples/sphere.json") + "' -q --size 0.05 -o ";
  const std::string cli = "'" + std::string(RDMESH_CLI_PATH) + "' ";
  const CliRun native = run_command("env", cli + input + "native.msh", dir.path());
  ASSERT_EQ(native.exit_code, 0) << native.output;
  const CliRun plain = run_command(
      "env", "GLIBC_TUNABLES=glibc.cpu.hwcaps=-FMA,-AVX2 " + cli + input + "plain.msh", dir.path());
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  const std::string a = bytes_of(dir.file("native.msh")), b = bytes_of(dir.file("plain.msh"));
  EXPECT_GT(a.size(), 100000u);
  EXPECT_TRUE(a == b) << "the sphere's mesh depends on glibc's choice of math functions ("
                      << a.size() << " and " << b.size() << " bytes)";
}

/// Removes every "seconds" entry (the phases' timings) from a report.
void drop_timings(nlohmann::json& j) {
  if (!j.is_object() && !j.is_array()) return;
  if (j.is_object()) j.erase("seconds");
  for (nlohmann::json& child : j) drop_timings(child);
}

/// Meshes `input` with --threads 1 and --threads 2: the same mesh bytes and the
/// same measured figures in the report (its timings aside).
void expect_same_for_thread_counts(const std::string& input, const std::string& args) {
  ScratchDir dir;
  for (const char* threads : {"1", "2"}) {
    const std::string name = std::string("t") + threads;
    const CliRun run = run_cli("'" + input + "' -q " + args + " --threads " + threads + " -o " +
                                   name + ".msh --report " + name + ".json",
                               dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.output;
  }
  const std::string a = bytes_of(dir.file("t1.msh")), b = bytes_of(dir.file("t2.msh"));
  // Above two chunks of the parallel loops (4096 items each), so that 2 threads share them.
  nlohmann::json r1 = nlohmann::json::parse(bytes_of(dir.file("t1.json")));
  nlohmann::json r2 = nlohmann::json::parse(bytes_of(dir.file("t2.json")));
  EXPECT_GT(r1.at("tets").get<std::size_t>(), 3 * 4096u);
  EXPECT_TRUE(a == b) << input << ": 1 and 2 threads wrote different bytes (" << a.size() << " and "
                      << b.size() << ")";
  EXPECT_GT(r1.at("optimization").at("min_dihedral_after_deg").get<double>(),
            r1.at("exudation").at("min_dihedral_before_deg").get<double>());
  // The refinement lanes ran on the threads asked for: the sizes a run derives
  // (a CAD part's thickness limits, gradings) may be called from two threads.
  ASSERT_GT(r1.at("refinement").at("lane_rounds").get<int>(), 0);
  EXPECT_EQ(r1.at("refinement").at("lane_threads").get<int>(), 1);
  EXPECT_EQ(r2.at("refinement").at("lane_threads").get<int>(), 2);
  for (nlohmann::json* r : {&r1, &r2}) {
    drop_timings(*r);
    r->erase("command_line");
    r->erase("output");
    r->at("criteria").erase("threads");
    r->at("refinement").erase("lane_threads");
  }
  EXPECT_EQ(r1.dump(1), r2.dump(1));
}

TEST(CliThreads, ImplicitSphereSameBytesForOneAndTwoThreads) {
  expect_same_for_thread_counts(source_path("samples/sphere.json"), "--size 0.1");
}

TEST(CliThreads, SharedStepSameBytesForOneAndTwoThreads) {
  RDMESH_REQUIRE_SHARED_DATA(part, "step/gmsh_Zylkopf.stp");
  expect_same_for_thread_counts(part, "");
}

TEST(CliThreads, SharedStepWithThinPartsSameBytesForOneAndTwoThreads) {
  // Its faces' thickness lowers the cell size below the default in places
  // (cad_sizes.cpp): a varying cell size the lanes evaluate on two threads.
  RDMESH_REQUIRE_SHARED_DATA(part, "step/gmsh_wrenchnut.stp");
  expect_same_for_thread_counts(part, "");
}

}  // namespace
}  // namespace rdmesh::test
