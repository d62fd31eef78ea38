// Exudation's queue order: blocks along a Morton curve first, worst first
// inside a block, and a single block (plain worst first) for small meshes.
#include "optimize/sliver_queue_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace rdmesh::detail {
namespace {

const Point3 kLo{-1, -1, -1}, kHi{1, 1, 1};

TEST(SliverQueueOrder, SmallMeshesAreOneBlockTakenWorstFirst) {
  const SliverQueueOrder order(kLo, kHi, 8 * SliverQueueOrder::kVerticesPerBlock - 1);
  EXPECT_EQ(order.block_bits(), 0);
  // Worse (larger cosine) first wherever the vertices are.
  EXPECT_GT(order.key(0.99, {0.9, 0.9, 0.9}), order.key(0.98, {-0.9, -0.9, -0.9}));
  EXPECT_GT(order.key(0.98, {-0.9, -0.9, -0.9}), order.key(0.97, {0.9, 0.9, 0.9}));
}

TEST(SliverQueueOrder, BlocksGrowByEightfoldSubdivisions) {
  const std::size_t per = SliverQueueOrder::kVerticesPerBlock;
  EXPECT_EQ(SliverQueueOrder(kLo, kHi, 8 * per).block_bits(), 3);
  EXPECT_EQ(SliverQueueOrder(kLo, kHi, 64 * per - 1).block_bits(), 3);
  EXPECT_EQ(SliverQueueOrder(kLo, kHi, 64 * per).block_bits(), 6);
  // The Morton curve's 8 bits per axis bound the subdivisions.
  EXPECT_EQ(SliverQueueOrder(kLo, kHi, std::size_t{1} << 62).block_bits(), 24);
}

TEST(SliverQueueOrder, BlockBeforeQualityThenWorstFirstInsideABlock) {
  const SliverQueueOrder order(kLo, kHi, 8 * SliverQueueOrder::kVerticesPerBlock);
  // 8 blocks: the octants, the one at the low corner first (x is the lowest
  // Morton bit: the octant of x > 0 comes next).
  const Point3 first{-0.5, -0.5, -0.5}, second{0.5, -0.5, -0.5}, last{0.5, 0.5, 0.5};
  EXPECT_GT(order.key(0.91, first), order.key(0.999, second));
  EXPECT_GT(order.key(0.91, second), order.key(0.999, last));
  EXPECT_GT(order.key(0.95, first), order.key(0.94, {-0.1, -0.9, -0.2}));
  EXPECT_EQ(order.key(0.95, first), order.key(0.95, {-0.1, -0.9, -0.2}));
}

TEST(SliverQueueOrder, KeysRankCosinesAsTheCosinesDoInsideABlock) {
  // Many vertices, all in one block (a tiny cube): the keys sort as the
  // cosines, to within the 2^-28 relative step the keys keep of them.
  const SliverQueueOrder order(kLo, kHi, std::size_t{1} << 24);
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> cosine(std::cos(25 * M_PI / 180), 1.0);
  std::uniform_real_distribution<double> offset(-1.0, -0.999);
  std::vector<std::pair<double, std::uint64_t>> entries;
  for (int i = 0; i < 10000; ++i) {
    const double c = cosine(rng);
    entries.push_back({c, order.key(c, {offset(rng), offset(rng), offset(rng)})});
  }
  std::sort(entries.begin(), entries.end());
  for (std::size_t i = 1; i < entries.size(); ++i) {
    EXPECT_LE(entries[i - 1].second, entries[i].second);
    if (entries[i].first - entries[i - 1].first > 1e-8) {
      EXPECT_LT(entries[i - 1].second, entries[i].second);
    }
  }
}

TEST(SliverQueueOrder, PointsOutsideTheBoxAndFlatBoxesGetKeys) {
  const SliverQueueOrder order(kLo, kHi, 1 << 20);
  // Clamped to the box's blocks: the far low corner shares the first block.
  EXPECT_EQ(order.key(0.95, {-5, -5, -5}) >> 40, order.key(0.95, kLo) >> 40);
  const SliverQueueOrder flat({0, 0, 0}, {0, 0, 0}, 1 << 20);
  EXPECT_EQ(flat.key(0.95, {0, 0, 0}), flat.key(0.95, {0, 0, 0}));
  EXPECT_GT(flat.key(0.96, {0, 0, 0}), flat.key(0.95, {0, 0, 0}));
}

}  // namespace
}  // namespace rdmesh::detail
