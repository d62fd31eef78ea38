// The refiner's bucket queue: the worst non-empty bucket first and, inside a
// bucket, the newest entry first, under interleaved pushes and pops, checked
// against a plain model of that rule.
#include "bucket_queue.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <map>
#include <random>
#include <vector>

namespace rdmesh::detail {
namespace {

TEST(BucketQueue, ServesTheWorstBucketFirstAndTheNewestEntryInside) {
  std::mt19937 rng(2026);
  std::uniform_int_distribution<std::size_t> bucket(0, 30);
  std::uniform_int_distribution<int> op(0, 2);
  BucketQueue<int> queue;
  std::map<std::size_t, std::vector<int>> model;  // bucket -> entries, oldest first
  std::size_t model_size = 0;
  int next = 0;
  std::size_t pops = 0;
  for (int step = 0; step < 100000 || !queue.empty(); ++step) {
    if (step < 100000 && (op(rng) != 0 || queue.empty())) {  // two pushes for one pop
      const std::size_t b = bucket(rng);
      queue.push(b, next);
      model[b].push_back(next);
      ++next;
      ++model_size;
    } else {
      const auto worst = std::prev(model.end());
      const int expected = worst->second.back();
      worst->second.pop_back();
      if (worst->second.empty()) model.erase(worst);
      --model_size;
      ASSERT_EQ(queue.pop(), expected) << "pop " << pops;
      ++pops;
    }
    ASSERT_EQ(queue.size(), model_size);
  }
  EXPECT_TRUE(model.empty());
  EXPECT_EQ(pops, static_cast<std::size_t>(next));
  EXPECT_GT(pops, 60000u);
}

TEST(BucketQueue, RefillsADrainedBucketAndStartsAfreshAfterRelease) {
  BucketQueue<int> queue;
  queue.push(5, 1);
  queue.push(2, 2);
  EXPECT_EQ(queue.pop(), 1);  // bucket 5 drained: the top moves down to 2
  queue.push(5, 3);           // and back up
  queue.push(7, 4);
  EXPECT_EQ(queue.pop(), 4);
  EXPECT_EQ(queue.pop(), 3);
  EXPECT_EQ(queue.pop(), 2);
  EXPECT_TRUE(queue.empty());
  queue.push(0, 6);  // bucket 0 is a bucket like the others
  queue.push(0, 7);
  EXPECT_EQ(queue.pop(), 7);
  queue.push(3, 8);
  queue.release();
  EXPECT_TRUE(queue.empty());
  EXPECT_EQ(queue.size(), 0u);
  queue.push(1, 9);
  EXPECT_EQ(queue.pop(), 9);
  EXPECT_TRUE(queue.empty());
}

}  // namespace
}  // namespace rdmesh::detail
