// for_chunks / parallel_for (rdmesh/parallel_for.h): the chunks depend on the
// item count only, every item is visited once, per-chunk sums folded in chunk
// order are the same bits for any thread count, and a body's exception reaches
// the caller.
#include "rdmesh/parallel_for.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace rdmesh {
namespace {

/// A floating-point sum whose value depends on the order of the additions.
double chunked_sum(std::size_t n, int threads) {
  std::vector<double> sums(chunk_count(n), 0.0);
  for_chunks(n, threads, [&](std::size_t k, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) sums[k] += 1.0 / (1.0 + std::sqrt(double(i)));
  });
  double total = 0;
  for (const double s : sums) total += s;
  return total;
}

TEST(ParallelFor, VisitsEveryItemOnceWhateverTheThreadCount) {
  const std::size_t n = 5 * kParallelChunk + 17;
  EXPECT_EQ(chunk_count(n), 6u);
  EXPECT_EQ(chunk_count(0), 0u);
  for (const int threads : {1, 2, 3, 8}) {
    std::vector<int> seen(n, 0);
    parallel_for(n, threads, [&](std::size_t i) { ++seen[i]; });
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(seen[i], 1) << "item " << i << ", " << threads;
  }
}

TEST(ParallelFor, ChunkedSumsAreTheSameBitsForAnyThreadCount) {
  const std::size_t n = 40 * kParallelChunk + 3;
  const double one = chunked_sum(n, 1);
  for (const int threads : {2, 3, 0}) EXPECT_EQ(chunked_sum(n, threads), one) << threads;
}

TEST(ParallelFor, ResolvesZeroToAllCores) {
  EXPECT_GE(resolve_threads(0), 1);
  EXPECT_EQ(resolve_threads(3), 3);
}

TEST(ParallelFor, RethrowsTheExceptionOfTheLowestChunk) {
  const std::size_t n = 10 * kParallelChunk;
  try {
    for_chunks(n, 2, [&](std::size_t k, std::size_t, std::size_t) {
      if (k == 3 || k == 7) throw std::runtime_error("chunk " + std::to_string(k));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "chunk 3");
  }
}

}  // namespace
}  // namespace rdmesh
