// The threads parallel_tasks() (rdmesh/parallel_for.h) lends its loops: started
// once and kept, so that a loop costs a wake-up, not a thread's creation and
// join. The refinement's lanes alone run about 250 two-thread steps at 9 M
// tets, and every phase after them runs loops of its own.
//
// One loop at a time has the pool; a loop that finds it taken (a loop run from
// inside another, or from a second thread of the host, such as the command's
// writer beside the check) starts threads of its own, as before. A forked
// child never uses its parent's pool: the pool's threads were not copied.
//
// A wake-up through the condition variable is slow on the virtual machines we
// measure on (a sleeping vCPU is woken through the hypervisor): 0.4 ms per
// loop on average, 22 ms of a 0.33 s two-thread run of the 147 k-tet sphere
// (57 loops), and as much again for the caller woken at the loop's end. So a
// helper that finished a loop watches for the next one for kSpin before it
// sleeps, and the caller watches for the helpers' end for kSpin before it
// sleeps: back-to-back loops (the lanes' steps, a phase's loops) then pass
// without a sleep. Both yield while they watch, so that another thread of the
// process (the writer beside the check, the heap populator) may have the core.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <system_error>
#include <thread>

#include "rdmesh/parallel_for.h"

namespace rdmesh::detail {
namespace {

/// How long a thread watches for what it waits for before it sleeps.
constexpr auto kSpin = std::chrono::microseconds(1000);

/// Watches `ready()` until it holds or kSpin passed (the caller then reads
/// its state under the lock either way).
template <class Ready>
void watch(Ready ready) {
  const auto until = std::chrono::steady_clock::now() + kSpin;
  for (unsigned k = 1; !ready(); ++k) {
    if ((k & 63) == 0 && std::chrono::steady_clock::now() > until) return;
    std::this_thread::yield();
  }
}

class WorkerPool {
 public:
  WorkerPool() : pid_(::getpid()), threads_(new std::vector<std::thread>) {}
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;
  ~WorkerPool() {
    // In a forked child the threads are the parent's: left alone (the child
    // ends with _exit anyway).
    if (::getpid() != pid_) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_.store(true, std::memory_order_relaxed);
    }
    wake_.notify_all();
    for (std::thread& t : *threads_) t.join();
    delete threads_;
  }

  bool start(std::size_t helpers, const std::function<void()>& job) {
    if (::getpid() != pid_ || busy_.exchange(true, std::memory_order_acquire)) return false;
    std::lock_guard<std::mutex> lock(mutex_);
    try {
      while (threads_->size() < helpers) threads_->emplace_back([this] { serve(); });
    } catch (const std::system_error&) {
      // No more threads to be had: the loop runs on those there are (each
      // invocation of the job takes tasks until none is left).
      if (threads_->empty()) {
        busy_.store(false, std::memory_order_release);
        return false;
      }
    }
    job_ = &job;
    to_start_.store(std::min(helpers, threads_->size()), std::memory_order_relaxed);
    wake_.notify_all();  // no system call when every helper is watching
    return true;
  }

  void finish() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      // The caller's own call of the job returned: every task is taken, so a
      // call not started yet would find none.
      to_start_.store(0, std::memory_order_relaxed);
    }
    watch([this] { return running_.load(std::memory_order_relaxed) == 0; });
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return running_.load(std::memory_order_relaxed) == 0; });
    job_ = nullptr;
    lock.unlock();
    busy_.store(false, std::memory_order_release);
  }

 private:
  void serve() {
    const auto called = [this] {
      return stop_.load(std::memory_order_relaxed) || to_start_.load(std::memory_order_relaxed) > 0;
    };
    for (;;) {
      watch(called);  // a hint: what counts is read under the lock
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, called);
      if (stop_.load(std::memory_order_relaxed)) return;
      to_start_.fetch_sub(1, std::memory_order_relaxed);
      running_.fetch_add(1, std::memory_order_relaxed);
      const std::function<void()>* job = job_;
      lock.unlock();
      (*job)();  // parallel_tasks' job catches what its bodies throw
      lock.lock();
      if (running_.fetch_sub(1, std::memory_order_relaxed) == 1) done_.notify_all();
    }
  }

  const pid_t pid_;
  std::vector<std::thread>* threads_;  ///< leaked in a forked child (see the destructor)
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void()>* job_ = nullptr;
  // Changed under mutex_ only; read without it while a thread watches.
  std::atomic<std::size_t> to_start_{0};  ///< calls of job_ no thread has begun
  std::atomic<std::size_t> running_{0};   ///< calls of job_ under way
  std::atomic<bool> stop_{false};
  std::atomic<bool> busy_{false};  ///< a loop has the pool
};

WorkerPool& pool() {
  static WorkerPool p;
  return p;
}

}  // namespace

bool start_pooled(std::size_t helpers, const std::function<void()>& job) {
  return pool().start(helpers, job);
}

void finish_pooled() { pool().finish(); }

}  // namespace rdmesh::detail
