// is_simple_chain and count_chain_components on small hand-made edge sets.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "rdmesh/mesh_measures.h"

namespace rdmesh {
namespace {

using Edges = std::vector<std::array<int, 2>>;

TEST(Chain, OpenPathInAnyOrderAndOrientation) {
  const Edges path{{7, 3}, {3, 12}, {12, 5}, {5, 100}};
  EXPECT_TRUE(is_simple_chain(path, false));
  EXPECT_FALSE(is_simple_chain(path, true));
  EXPECT_TRUE(is_simple_chain({{5, 100}, {12, 3}, {7, 3}, {5, 12}}, false));
  EXPECT_TRUE(is_simple_chain({{0, 1}}, false));
  EXPECT_EQ(count_chain_components(path), 1);
}

TEST(Chain, Cycle) {
  const Edges cycle{{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  EXPECT_TRUE(is_simple_chain(cycle, true));
  EXPECT_FALSE(is_simple_chain(cycle, false));
  EXPECT_TRUE(is_simple_chain({{2, 0}, {0, 1}, {2, 1}}, true));  // triangle, mixed orientation
  EXPECT_EQ(count_chain_components(cycle), 1);
}

TEST(Chain, BrokenChainHasTwoComponents) {
  const Edges broken{{0, 1}, {1, 2}, {3, 4}, {4, 5}};
  EXPECT_FALSE(is_simple_chain(broken, false));
  EXPECT_FALSE(is_simple_chain(broken, true));
  EXPECT_EQ(count_chain_components(broken), 2);
  // A path plus a separate cycle: right degrees, two ends, yet not one chain.
  const Edges path_and_cycle{{0, 1}, {1, 2}, {5, 6}, {6, 7}, {7, 5}};
  EXPECT_FALSE(is_simple_chain(path_and_cycle, false));
  EXPECT_EQ(count_chain_components(path_and_cycle), 2);
  // Two disjoint cycles.
  EXPECT_FALSE(is_simple_chain({{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}}, true));
}

TEST(Chain, BranchingSetIsNotAChain) {
  const Edges star{{0, 1}, {0, 2}, {0, 3}};
  EXPECT_FALSE(is_simple_chain(star, false));
  EXPECT_EQ(count_chain_components(star), 1);
  // A cycle with a tail: one vertex of degree 3.
  EXPECT_FALSE(is_simple_chain({{0, 1}, {1, 2}, {2, 0}, {2, 3}}, false));
  EXPECT_FALSE(is_simple_chain({{0, 1}, {1, 2}, {2, 0}, {2, 3}}, true));
}

TEST(Chain, DuplicatedOrDegenerateEdges) {
  EXPECT_FALSE(is_simple_chain({{0, 1}, {1, 2}, {1, 2}}, false));
  EXPECT_FALSE(is_simple_chain({{0, 1}, {1, 2}, {2, 1}}, false));  // reversed duplicate
  EXPECT_FALSE(is_simple_chain({{0, 1}, {1, 0}}, true));           // a "cycle" of two edges
  EXPECT_FALSE(is_simple_chain({{0, 1}, {1, 1}}, false));          // self loop
  EXPECT_FALSE(is_simple_chain({{0, 1}, {1, 2}, {2, 3}, {1, 2}}, false));
}

TEST(Chain, EmptySet) {
  EXPECT_FALSE(is_simple_chain({}, false));
  EXPECT_FALSE(is_simple_chain({}, true));
  EXPECT_EQ(count_chain_components({}), 0);
}

}  // namespace
}  // namespace rdmesh
