// The refiner's 4-ary heap pops exactly the sequence std::priority_queue pops
// (the refinement's decisions depend on that order), under interleaved pushes
// and pops with many equal priorities.
#include "worst_first_heap.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <queue>
#include <random>
#include <vector>

namespace rdmesh::detail {
namespace {

struct Entry {
  double priority;
  std::uint32_t stamp;
  bool operator<(const Entry& o) const {
    return priority < o.priority || (priority == o.priority && stamp > o.stamp);
  }
};

TEST(WorstFirstHeap, PopsTheSameSequenceAsStdPriorityQueue) {
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> coarse(0, 40);  // many ties in priority
  std::uniform_int_distribution<int> op(0, 2);
  WorstFirstHeap<Entry> heap;
  std::priority_queue<Entry> reference;
  std::uint32_t stamp = 0;
  std::vector<Entry> popped, expected;
  for (int step = 0; step < 200000; ++step) {
    if (op(rng) != 0 || heap.empty()) {  // two pushes for one pop: the heap grows
      const Entry e{coarse(rng) * 0.25, ++stamp};
      heap.push(e);
      reference.push(e);
    } else {
      popped.push_back(heap.top());
      expected.push_back(reference.top());
      heap.pop();
      reference.pop();
    }
    ASSERT_EQ(heap.size(), reference.size());
  }
  while (!heap.empty()) {
    popped.push_back(heap.top());
    expected.push_back(reference.top());
    heap.pop();
    reference.pop();
  }
  ASSERT_TRUE(reference.empty());
  ASSERT_EQ(popped.size(), expected.size());
  for (std::size_t k = 0; k < popped.size(); ++k) {
    ASSERT_EQ(popped[k].priority, expected[k].priority) << "pop " << k;
    ASSERT_EQ(popped[k].stamp, expected[k].stamp) << "pop " << k;
  }
  EXPECT_GT(popped.size(), 60000u);
  heap.release();
  EXPECT_TRUE(heap.empty());
}

}  // namespace
}  // namespace rdmesh::detail
