// Progress on stderr: every phase that takes longer than the delay (1 s, or
// RDMESH_PROGRESS_DELAY) is shown and ends with "PHASE: done in T s"; -q shows none.
#include <gtest/gtest.h>

#include <cstdlib>

#include "cli_runner.h"

namespace rdmesh::test {
namespace {

/// Sets RDMESH_PROGRESS_DELAY for the runs of one test.
class ProgressDelay {
 public:
  explicit ProgressDelay(const char* seconds) { ::setenv("RDMESH_PROGRESS_DELAY", seconds, 1); }
  ~ProgressDelay() { ::unsetenv("RDMESH_PROGRESS_DELAY"); }
};

TEST(CliProgress, EveryPhaseLongerThanTheDelayIsShown) {
  ProgressDelay delay("0");
  ScratchDir dir;
  const std::string args = std::string("'") + source_path("samples/cube.json") +
                           "' -o out.msh --size 0.4 --report r.json --picture p.png "
                           "--picture-size 400x320 --threads ";
  const CliRun run = run_cli(args + "1", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* phase :
       {"reading ", "checking the criteria: done in", "protecting sharp features: done in",
        "inserting initial points: done in", "refining: done in", "exuding slivers: done in",
        "extracting the mesh: done in", "checking the mesh against the model: done in",
        "writing out.msh: done in", "drawing p.png: done in", "writing r.json: done in"}) {
    EXPECT_NE(run.output.find(phase), std::string::npos) << "no '" << phase << "' in\n"
                                                         << run.output;
  }
  // On two threads the mesh file is written while the mesh is checked: one phase.
  const CliRun two = run_cli(args + "2", dir.path());
  ASSERT_EQ(two.exit_code, 0) << two.output;
  EXPECT_NE(two.output.find("checking the mesh against the model, writing out.msh: done in"),
            std::string::npos)
      << two.output;
  EXPECT_EQ(two.output.find("\nwriting out.msh"), std::string::npos) << two.output;
  EXPECT_NE(two.output.find("drawing p.png: done in"), std::string::npos) << two.output;
}

TEST(CliProgress, QuietAndShortRunsShowNone) {
  ScratchDir dir;
  const std::string sample = std::string("'") + source_path("samples/sphere.json") + "'";
  {
    ProgressDelay delay("0");
    const CliRun run = run_cli(sample + " -o out.msh --size 0.5 -q", dir.path());
    ASSERT_EQ(run.exit_code, 0) << run.output;
    EXPECT_EQ(run.output, "");
  }
  ProgressDelay delay("30");  // no phase of this run takes 30 s
  const CliRun run = run_cli(sample + " -o out.msh --size 0.5", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output.find("done in"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace rdmesh::test
