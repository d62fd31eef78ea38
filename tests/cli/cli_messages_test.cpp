// What a user sees when the command line or the input path is wrong: one line
// "rdmesh: error: ...", exit code 2, the option named with what it accepts, and
// the same words for a missing file or a directory whatever the input's kind.
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_runner.h"

namespace rdmesh::test {
namespace {

const char* kSphere =
    R"({"bbox": [-1.2,-1.2,-1.2,1.2,1.2,1.2], "functions": {"s": "x^2+y^2+z^2-1"}})";

/// Runs `args` in a directory holding in.json and expects exit 2 with one line
/// containing `expected`, and nothing written.
void expect_refused(const std::string& args, const std::string& expected) {
  ScratchDir dir;
  dir.write("in.json", kSphere);
  const CliRun run = run_cli(args, dir.path());
  EXPECT_EQ(run.exit_code, 2) << args << "\n" << run.output;
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
  EXPECT_EQ(run.output.rfind("rdmesh: error: ", 0), 0u) << run.output;
  EXPECT_NE(run.output.find(expected), std::string::npos)
      << args << ": the message lacks '" << expected << "': " << run.output;
  EXPECT_EQ(dir.entries(), 1u) << args << ": something was written";
}

TEST(CliMessages, GmshStyleSingleDashFlagsAreUnknownOptions) {
  expect_refused("in.json -optimize", "unknown option '-optimize'");
  expect_refused("in.json -order 2", "unknown option '-order'");
  expect_refused("in.json -3", "unknown option '-3'");
  expect_refused("in.json -oout.vtu", "unknown option '-oout.vtu'");
  expect_refused("view in.json -clscale 2", "unknown option '-clscale'");
  // The message says how rdmesh's options look.
  expect_refused("in.json -optimize", "two dashes");
}

TEST(CliMessages, NegativeNumbersAreValuesNotFlags) {
  // --size -0.1 reaches the criteria check (a size must be positive), not the flag check.
  expect_refused("in.json -o out.msh --size -0.1", "size");
  ScratchDir dir;
  dir.write("in.json", kSphere);
  const CliRun run = run_cli("in.json -o out.msh --size -0.1", dir.path());
  EXPECT_EQ(run.output.find("unknown option"), std::string::npos) << run.output;
}

TEST(CliMessages, ParseErrorsNameTheOptionAndWhatItAccepts) {
  expect_refused("in.json --size abc", "--size: 'abc' is not allowed; expected a length > 0");
  expect_refused("in.json --size nan", "--size: 'nan' is not allowed");
  expect_refused("in.json --features fast",
                 "--features: 'fast' is not allowed; expected protect or refine");
  expect_refused("in.json --check everything",
                 "--check: 'everything' is not allowed; expected cheap or full");
  expect_refused("in.json --feature-angle 200",
                 "--feature-angle: '200' is not allowed; expected an angle in degrees in [0, 180]");
  expect_refused("in.json --exude-bound 0",
                 "--exude-bound: '0' is not allowed; expected an angle in degrees in (0, 90]");
  expect_refused("in.json --exude-bound 91", "--exude-bound: '91' is not allowed");
  expect_refused("in.json --exude-bound nan", "--exude-bound: 'nan' is not allowed");
  expect_refused("in.json --time-limit -3",
                 "--time-limit: '-3' is not allowed; expected a number "
                 "of seconds >= 0");
  expect_refused("in.json --max-elements 0", "--max-elements: '0' is not allowed");
  expect_refused("in.json --size", "--size needs a value: a length > 0");
  expect_refused("in.json --bogus 3", "unknown option '--bogus'");
  expect_refused("in.json --bogus=3", "unknown option '--bogus'");
  expect_refused("in.json other.json", "unexpected argument 'other.json'");
  expect_refused("--size 1", "no input file given");
}

TEST(CliMessages, MissingFilesAreWordedTheSameForEveryKind) {
  for (const char* name : {"a.json", "a.step", "a.stp", "a.brep", "a.iges", "a.igs", "a.off",
                           "a.stl", "a.obj", "a.ply"}) {
    expect_refused(std::string(name) + " -o out.msh", std::string(name) + ": no such file");
  }
  expect_refused("view a.msh -o a.png", "a.msh: no such file");
}

TEST(CliMessages, ADirectoryIsADirectory) {
  for (const char* name : {"d", "d.step", "d.json", "d.stl"}) {
    ScratchDir dir;
    std::filesystem::create_directory(dir.path() / name);
    const CliRun run = run_cli(std::string(name) + " -o out.msh", dir.path());
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_EQ(run.output, std::string("rdmesh: error: ") + name + ": is a directory\n");
  }
  ScratchDir dir;
  std::filesystem::create_directory(dir.path() / "m.msh");
  const CliRun run = run_cli("view m.msh -o m.png", dir.path());
  EXPECT_EQ(run.output, "rdmesh: error: m.msh: is a directory\n");
}

TEST(CliMessages, TheSummaryPrintsShortTimesWithoutFixedZeros) {
  ScratchDir dir;
  const CliRun run =
      run_cli(std::string("'") + source_path("samples/sphere.json") + "' -o out.msh --size 0.5",
              dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::size_t at = run.output.find("time: ");
  ASSERT_NE(at, std::string::npos) << run.output;
  const std::string line = run.output.substr(at, run.output.find('\n', at) - at);
  EXPECT_EQ(line.find("0.00 s"), std::string::npos) << line;
  EXPECT_EQ(run.output.find("0.000000"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace rdmesh::test
