// Deterministic parallel loops. [0, n) is cut into chunks whose bounds depend
// on n alone, never on the number of threads; each chunk is processed whole by
// one thread and the caller combines per-chunk results in chunk order. A
// result is then the same bits for any thread count, as long as the body of a
// chunk only reads shared state and writes what belongs to its own items or
// its own chunk.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <thread>
#include <vector>

namespace rdmesh {

/// The threads a run uses: `requested`, or all cores (std::thread::hardware_concurrency,
/// at least 1) when it is 0.
inline int resolve_threads(int requested) {
  if (requested > 0) return requested;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// The parallel_tasks calls running on more than one thread now, in the
/// whole process. The command's heap populator (cli/heap_setup.cpp) waits
/// while there are some: the cores are busy then, and a lane preempted by it
/// would hold up the other at the end of the step.
inline std::atomic<int>& parallel_regions() {
  static std::atomic<int> running{0};
  return running;
}

/// Items per chunk of for_chunks.
constexpr std::size_t kParallelChunk = 4096;

/// The number of chunks of [0, n): chunk k is [k * kParallelChunk, min(n, (k + 1) *
/// kParallelChunk)).
inline std::size_t chunk_count(std::size_t n) { return (n + kParallelChunk - 1) / kParallelChunk; }

namespace detail {
/// Starts job() on `helpers` threads of the process's worker pool (kept between
/// loops, core/src/worker_pool.cpp) and returns at once; false, with nothing
/// started, when another loop has the pool or this process is a forked child.
bool start_pooled(std::size_t helpers, const std::function<void()>& job);
/// After a successful start_pooled and the caller's own job(): waits for the
/// calls under way (those not begun are dropped: every task is taken).
void finish_pooled();
}  // namespace detail

/// Calls body(task) once for every task in [0, n), on up to `threads` threads
/// (the calling one among them; 0: all cores), each task whole on one thread.
/// The others are the worker pool's, or threads of its own when another loop
/// has the pool. An exception thrown by a body is rethrown here after every
/// thread stopped (the one of the lowest task when several threw).
template <class Body>
void parallel_tasks(std::size_t n, int threads, Body body) {
  const auto workers = static_cast<std::size_t>(
      std::min<std::size_t>(static_cast<std::size_t>(resolve_threads(threads)), n));
  if (workers <= 1) {
    for (std::size_t k = 0; k < n; ++k) body(k);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> errors(n);
  const std::function<void()> work = [&] {
    for (std::size_t k = next++; k < n; k = next++) {
      try {
        body(k);
      } catch (...) {
        errors[k] = std::current_exception();
      }
    }
  };
  struct Running {
    Running() { parallel_regions().fetch_add(1, std::memory_order_relaxed); }
    ~Running() { parallel_regions().fetch_sub(1, std::memory_order_relaxed); }
  } running;
  if (detail::start_pooled(workers - 1, work)) {
    work();
    detail::finish_pooled();
  } else {
    std::vector<std::thread> pool;
    pool.reserve(workers - 1);
    for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
  }
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

/// Calls body(chunk, begin, end) once for every chunk of [0, n), on up to
/// `threads` threads (parallel_tasks, a chunk per task).
template <class Body>
void for_chunks(std::size_t n, int threads, Body body) {
  parallel_tasks(chunk_count(n), threads, [&](std::size_t k) {
    body(k, k * kParallelChunk, std::min(n, (k + 1) * kParallelChunk));
  });
}

/// Calls body(i) for every i in [0, n) (for_chunks, item by item).
template <class Body>
void parallel_for(std::size_t n, int threads, Body body) {
  for_chunks(n, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) body(i);
  });
}

}  // namespace rdmesh
