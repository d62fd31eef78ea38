// A refinement lane's cell queue (lane_cell_queue.h): the blocks of space in
// Morton order first, then inside a block BucketQueue's rule (the worst
// bucket, the newest entry first), under interleaved pushes and pops,
// checked against a plain model of that rule; and the blocks' counts.
#include "lane_cell_queue.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "morton_blocks.h"

namespace rdmesh::detail {
namespace {

TEST(MortonBlocks, CountsGrowByEightfoldSubdivisionsUpToTheCap) {
  EXPECT_EQ(MortonBlocks::bits_for(7.9 * 100, 100), 0);
  EXPECT_EQ(MortonBlocks::bits_for(8 * 100, 100), 3);
  EXPECT_EQ(MortonBlocks::bits_for(64 * 100 - 1, 100), 3);
  EXPECT_EQ(MortonBlocks::bits_for(64 * 100, 100), 6);
  EXPECT_EQ(MortonBlocks::bits_for(1e30, 1), 24);
  EXPECT_EQ(MortonBlocks::bits_for(1e30, 1, 12), 12);
  EXPECT_EQ(MortonBlocks::bits_for(1e30, 1, 13), 12);
}

TEST(MortonBlocks, OctantsInMortonOrderAndPointsOutsideClamped) {
  const MortonBlocks blocks({0, 0, 0}, {2, 1, 1}, 3);  // the cube [0, 2]^3
  EXPECT_EQ(blocks.count(), 8u);
  EXPECT_EQ(blocks.block({0.5, 0.5, 0.5}), 0u);
  EXPECT_EQ(blocks.block({1.5, 0.5, 0.5}), 1u);  // x is the lowest bit
  EXPECT_EQ(blocks.block({0.5, 1.5, 0.5}), 2u);
  EXPECT_EQ(blocks.block({0.5, 0.5, 1.5}), 4u);
  EXPECT_EQ(blocks.block({1.5, 1.5, 1.5}), 7u);
  EXPECT_EQ(blocks.block({-9, -9, -9}), 0u);
  EXPECT_EQ(blocks.block({9, 9, 9}), 7u);
  EXPECT_EQ(MortonBlocks({0, 0, 0}, {1, 1, 1}, 0).block({0.9, 0.9, 0.9}), 0u);
}

TEST(LaneCellQueue, BlocksInCurveOrderThenTheWorstBucketAndTheNewestEntry) {
  // Cells of a small triangulation stand for the entries; each gets a
  // centre in one of 64 blocks of the unit cube.
  Triangulation tr;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 200; ++i)
    tr.insert(Weighted_point(Kernel::Point_3(unit(rng), unit(rng), unit(rng)), 0));
  std::vector<Cell_handle> cells;
  for (auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) {
    c->info().circumcenter = {unit(rng), unit(rng), unit(rng)};
    cells.push_back(c);
  }
  ASSERT_GT(cells.size(), 500u);
  const MortonBlocks blocks({0, 0, 0}, {1, 1, 1}, 6);
  LaneCellQueue queue;
  queue.set_blocks(&blocks);
  // (block, bucket) -> entries' ids, oldest first.
  std::map<std::pair<std::uint64_t, std::size_t>, std::vector<std::uint32_t>> model;
  std::uniform_int_distribution<std::size_t> pick(0, cells.size() - 1), bucket(0, 20);
  std::uniform_int_distribution<int> op(0, 2);
  std::uint32_t next = 0;
  std::size_t pops = 0;
  for (int step = 0; step < 20000 || !queue.empty(); ++step) {
    if (step < 20000 && (op(rng) != 0 || queue.empty())) {
      const Cell_handle c = cells[pick(rng)];
      const std::size_t b = bucket(rng);
      queue.push(b, ElementEntry{1.0, c, next, -1});
      // Lowest block first, then the largest bucket: key the model so that
      // its first element is the one to come out.
      model[{blocks.block(c->info().circumcenter), 1000 - b}].push_back(next);
      ++next;
    } else {
      const ElementEntry e = queue.pop();
      auto first = model.begin();
      ASSERT_NE(first, model.end());
      ASSERT_EQ(e.stamp, first->second.back()) << "pop " << pops;
      first->second.pop_back();
      if (first->second.empty()) model.erase(first);
      ++pops;
    }
    std::size_t size = 0;
    for (const auto& [key, ids] : model) size += ids.size();
    ASSERT_EQ(queue.size(), size);
  }
  EXPECT_TRUE(model.empty());
  EXPECT_EQ(pops, next);
}

TEST(LaneCellQueue, KeepsItsBlocksAfterRelease) {
  // A refiner frees its empty queues after refining, and may refine again
  // (a run that finishes after a refused restart): the blocks still hold.
  Triangulation tr;
  for (int i = 0; i < 8; ++i)
    tr.insert(Weighted_point(Kernel::Point_3(i & 1, (i >> 1) & 1, (i >> 2) & 1), 0));
  std::vector<Cell_handle> cells;
  for (auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) cells.push_back(c);
  ASSERT_GE(cells.size(), 2u);
  cells[0]->info().circumcenter = {0.9, 0.9, 0.9};  // the last of 8 blocks
  cells[1]->info().circumcenter = {0.1, 0.1, 0.1};  // the first
  const MortonBlocks blocks({0, 0, 0}, {1, 1, 1}, 3);
  LaneCellQueue queue;
  queue.set_blocks(&blocks);
  for (int round = 0; round < 2; ++round) {
    queue.push(9, ElementEntry{1.0, cells[0], 1, -1});  // worse bucket, later block
    queue.push(0, ElementEntry{1.0, cells[1], 2, -1});
    EXPECT_EQ(queue.pop().stamp, 2u) << "round " << round;
    EXPECT_EQ(queue.pop().stamp, 1u) << "round " << round;
    ASSERT_TRUE(queue.empty());
    queue.release();
  }
}

TEST(LaneCellQueue, WithoutBlocksItIsTheBucketQueue) {
  Triangulation tr;
  for (int i = 0; i < 8; ++i)
    tr.insert(Weighted_point(Kernel::Point_3(i & 1, (i >> 1) & 1, (i >> 2) & 1), 0));
  const Cell_handle c = tr.all_cells_begin();
  LaneCellQueue queue;  // no set_blocks: one block
  BucketQueue<std::uint32_t> plain;
  for (std::uint32_t i = 0; i < 100; ++i) {
    queue.push(i % 7, ElementEntry{1.0, c, i, -1});
    plain.push(i % 7, i);
  }
  while (!plain.empty()) ASSERT_EQ(queue.pop().stamp, plain.pop());
  EXPECT_TRUE(queue.empty());
}

}  // namespace
}  // namespace rdmesh::detail
