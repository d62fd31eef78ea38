// When a run fails (MeshRun::failed, run::failure_reason): the CLI's exit 4
// and the Python module's FidelityError both follow these rules.
#include <gtest/gtest.h>

#include "rdmesh/mesh_run.h"

namespace rdmesh::run {
namespace {

TEST(RunFailure, AMeshWithInvertedTetsFailsWhateverTheInput) {
  Options opt;
  MeshRun run;  // no fidelity report: an implicit domain
  EXPECT_FALSE(run.failed());
  EXPECT_EQ(failure_reason(opt, run), "");

  run.quality.inverted_tets = 1;
  EXPECT_TRUE(run.failed());
  EXPECT_EQ(failure_reason(opt, run), "1 tetrahedron is inverted or flat (signed volume <= 0)");
  run.quality.inverted_tets = 3;
  EXPECT_EQ(failure_reason(opt, run), "3 tetrahedra are inverted or flat (signed volume <= 0)");
}

TEST(RunFailure, InvertedTetsAndAFailedFidelityCheckAreBothNamed) {
  Options opt;
  MeshRun run;
  run.fidelity = FidelityReport{};
  EXPECT_FALSE(run.failed());  // a passed check
  run.fidelity->passed = false;
  run.fidelity->problems = {"curve 3 (edge_3) is not one chain of edges"};
  EXPECT_TRUE(run.failed());
  EXPECT_EQ(failure_reason(opt, run).rfind("the mesh does not match the model: curve 3", 0), 0u)
      << failure_reason(opt, run);
  run.quality.inverted_tets = 2;
  const std::string reason = failure_reason(opt, run);
  EXPECT_EQ(reason.rfind("2 tetrahedra are inverted or flat", 0), 0u) << reason;
  EXPECT_NE(reason.find("; the mesh does not match the model: curve 3"), std::string::npos)
      << reason;
}

}  // namespace
}  // namespace rdmesh::run
