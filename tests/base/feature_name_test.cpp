// One way to name a feature in every message and report.
#include "rdmesh/feature_name.h"

#include <gtest/gtest.h>

namespace rdmesh {
namespace {

TEST(FeatureName, KindIdAndNameWhenThereIsOne) {
  EXPECT_EQ(feature_name(CornerId{3}), "corner 3");
  EXPECT_EQ(feature_name(CurveId{7}, "rim"), "curve 7 (rim)");
  EXPECT_EQ(feature_name(CurveId{7}), "curve 7");
  EXPECT_EQ(feature_name(PatchId{2}, "top face"), "patch 2 (top face)");
  EXPECT_EQ(feature_name(PatchId{2}, ""), "patch 2");
  EXPECT_EQ(feature_name(SubdomainId{1}, "shell"), "subdomain 1 (shell)");
}

}  // namespace
}  // namespace rdmesh
