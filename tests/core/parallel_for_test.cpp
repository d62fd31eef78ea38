// for_chunks / parallel_for (rdmesh/parallel_for.h): the chunks depend on the
// item count only, every item is visited once, per-chunk sums folded in chunk
// order are the same bits for any thread count, and a body's exception reaches
// the caller.
#include "rdmesh/parallel_for.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
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

/// The kernel's ids of the threads other than the caller's that ran tasks of
/// one loop of n tasks: every task waits, up to 10 s, until threads - 1 such
/// threads have run one, so that every thread does.
std::set<pid_t> helper_threads(std::size_t n, int threads) {
  std::mutex m;
  std::condition_variable helped;
  std::set<pid_t> ids;
  const pid_t caller = ::gettid();
  const auto all = static_cast<std::size_t>(threads - 1);
  parallel_tasks(n, threads, [&](std::size_t) {
    std::unique_lock<std::mutex> lock(m);
    if (::gettid() != caller && ids.insert(::gettid()).second) helped.notify_all();
    helped.wait_for(lock, std::chrono::seconds(10), [&] { return ids.size() >= all; });
  });
  return ids;
}

/// Whether thread `tid` of this process is still running.
bool thread_alive(pid_t tid) {
  return std::filesystem::exists("/proc/self/task/" + std::to_string(tid));
}

TEST(ParallelFor, ItsHelperThreadsOutliveTheLoopsAndServeTheNextOnes) {
  std::set<pid_t> seen;
  for (int loop = 0; loop < 5; ++loop) {
    const std::set<pid_t> helpers = helper_threads(16, 2);
    ASSERT_EQ(helpers.size(), 1u) << "no second thread took a task";
    seen.insert(helpers.begin(), helpers.end());
  }
  for (const pid_t tid : seen) EXPECT_TRUE(thread_alive(tid)) << "helper " << tid << " ended";
  // Threads started for each loop would all be new ones: the pool has at most
  // as many as the most a loop of this process asked for (8, in this file).
  EXPECT_LE(seen.size(), 7u);
  const std::set<pid_t> three = helper_threads(24, 3);
  EXPECT_EQ(three.size(), 2u);
  for (const pid_t tid : three) EXPECT_TRUE(thread_alive(tid));
}

TEST(ParallelFor, BackToBackLoopsAndLoopsAfterAPauseRunEveryTask) {
  // The pool's helpers watch for the next loop for a while before they sleep,
  // and the caller watches for their end: loops that follow at once, loops
  // after a pause longer than the watch, and a helper task that outlasts the
  // caller's watch must each run every task exactly once.
  std::vector<int> counts(2, 0);
  for (int loop = 0; loop < 2000; ++loop) {
    std::atomic<int> sum{0};
    parallel_tasks(2, 2, [&](std::size_t k) { sum += static_cast<int>(k) + 1; });
    ASSERT_EQ(sum.load(), 3) << "loop " << loop;
  }
  for (int loop = 0; loop < 3; ++loop) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    std::vector<int> seen(4, 0);
    parallel_tasks(4, 2, [&](std::size_t k) {
      if (k == 0) std::this_thread::sleep_for(std::chrono::milliseconds(5));
      ++seen[k];
    });
    for (const int s : seen) EXPECT_EQ(s, 1);
  }
}

TEST(ParallelFor, ALoopInsideALoopAndLoopsFromTwoThreadsAllRunEveryTask) {
  // The inner loops find the pool taken and start threads of their own.
  const std::size_t outer = 6, inner = 3 * kParallelChunk + 5;
  std::vector<std::vector<int>> seen(outer, std::vector<int>(inner, 0));
  parallel_tasks(outer, 2, [&](std::size_t k) {
    parallel_for(inner, 2, [&](std::size_t i) { ++seen[k][i]; });
  });
  for (std::size_t k = 0; k < outer; ++k)
    for (std::size_t i = 0; i < inner; ++i) ASSERT_EQ(seen[k][i], 1) << k << " " << i;
  // Two host threads looping at once: one has the pool, the other its own threads.
  const std::size_t n = 20 * kParallelChunk;
  double a = 0, b = 0;
  std::thread other([&] {
    for (int r = 0; r < 20; ++r) b = chunked_sum(n, 2);
  });
  for (int r = 0; r < 20; ++r) a = chunked_sum(n, 2);
  other.join();
  EXPECT_EQ(a, chunked_sum(n, 1));
  EXPECT_EQ(b, a);
}

TEST(ParallelFor, RunsInAForkedChildOfAProcessWhosePoolHasThreads) {
  ASSERT_EQ(helper_threads(16, 2).size(), 1u);  // the parent's pool has its thread
  const std::size_t n = 8 * kParallelChunk + 1;
  const double expected = chunked_sum(n, 1);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    // The child has no copy of the pool's thread: its loops must not wait for it.
    const bool same = chunked_sum(n, 2) == expected && helper_threads(16, 2).size() == 1;
    ::_exit(same ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "the child did not finish (status " << status << ")";
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
}  // namespace rdmesh
