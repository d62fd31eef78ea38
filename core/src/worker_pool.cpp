// The threads parallel_tasks() (rdmesh/parallel_for.h) lends its loops: started
// once and kept, so that a loop costs a wake-up, not a thread's creation and
// join. The refinement's lanes alone run about 250 two-thread steps at 9 M
// tets, and every phase after them runs loops of its own.
//
// One loop at a time has the pool; a loop that finds it taken (a loop run from
// inside another, or from a second thread of the host, such as the command's
// writer beside the check) starts threads of its own, as before. A forked
// child never uses its parent's pool: the pool's threads were not copied.
#include <unistd.h>

#include <condition_variable>
#include <functional>
#include <mutex>
#include <system_error>

#include "rdmesh/parallel_for.h"

namespace rdmesh::detail {
namespace {

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
      stop_ = true;
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
    to_start_ = std::min(helpers, threads_->size());
    wake_.notify_all();
    return true;
  }

  void finish() {
    std::unique_lock<std::mutex> lock(mutex_);
    // The caller's own call of the job returned: every task is taken, so a
    // call not started yet would find none.
    to_start_ = 0;
    done_.wait(lock, [this] { return running_ == 0; });
    job_ = nullptr;
    lock.unlock();
    busy_.store(false, std::memory_order_release);
  }

 private:
  void serve() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [this] { return stop_ || to_start_ > 0; });
      if (stop_) return;
      --to_start_;
      ++running_;
      const std::function<void()>* job = job_;
      lock.unlock();
      (*job)();  // parallel_tasks' job catches what its bodies throw
      lock.lock();
      if (--running_ == 0) done_.notify_all();
    }
  }

  const pid_t pid_;
  std::vector<std::thread>* threads_;  ///< leaked in a forked child (see the destructor)
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void()>* job_ = nullptr;
  std::size_t to_start_ = 0;  ///< calls of job_ no thread has begun
  std::size_t running_ = 0;   ///< calls of job_ under way
  bool stop_ = false;
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
