// RDMESH_DEBUG_ASSERT: in a build with RDMESH_DEBUG_CHECKS a broken invariant
// throws InternalError naming where and what; otherwise the condition is not even
// evaluated. CI runs this file in both kinds of build (the sanitizer build has the
// checks on).
#include "rdmesh/debug_assert.h"

#include <gtest/gtest.h>

#include <string>

namespace rdmesh {
namespace {

TEST(DebugAssert, FailureThrowsInternalErrorWithFileLineAndCondition) {
  try {
    detail::debug_assert_failed("cells.cpp", 42, "label >= 0", "cell 7");
    FAIL() << "no exception";
  } catch (const InternalError& e) {
    EXPECT_EQ(std::string(e.what()), "invariant broken at cells.cpp:42: label >= 0 (cell 7)");
  }
}

TEST(DebugAssert, ChecksExactlyWhenTheBuildAsksForThem) {
  int evaluated = 0;
  auto holds = [&](bool value) {
    ++evaluated;
    return value;
  };
  EXPECT_NO_THROW(RDMESH_DEBUG_ASSERT(holds(true), "holds"));
#if RDMESH_DEBUG_CHECKS
  EXPECT_THROW(RDMESH_DEBUG_ASSERT(holds(false), "broken"), InternalError);
  EXPECT_EQ(evaluated, 2);
#else
  EXPECT_NO_THROW(RDMESH_DEBUG_ASSERT(holds(false), "broken"));
  EXPECT_EQ(evaluated, 0);
#endif
}

}  // namespace
}  // namespace rdmesh
