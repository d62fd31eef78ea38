// The command's heap, backed by transparent huge pages as it grows.
//
// A run allocates its memory in many small steps (OpenCASCADE's shapes while
// reading, the triangulation's cell blocks while refining), and on the shared
// virtual machines we measure on every fresh 4 KiB page costs a fault: 6-10%
// of a CAD run, and 8% of a 9 M-tet sphere whose heap reaches 1.9 GB. Huge
// pages take 512 times fewer faults and TLB entries. glibc only asks for them
// when told to (the glibc.malloc.hugetlb tunable, an environment variable read
// at process start), so the command does it by hand:
//  - the heap grows by kRegion at a time, large blocks come from the heap too
//    (up to glibc's 32 MiB ceiling), and freed memory stays there for reuse (a
//    restart of refinement allocates a new triangulation of about the old
//    one's size);
//  - every thread allocates from this one heap (no arena per thread);
//  - every time the heap has grown, the new part is advised MADV_HUGEPAGE. The
//    command replaces the global operator new for this (allowed to a program,
//    not to a library): after each allocation it compares the heap's end with
//    what it advised already, which costs a comparison, and a block above the
//    ceiling (its own mapping) is advised whole.
// A region is advised before the blocks in it are written, except the first
// page of the block whose allocation grew the heap (malloc writes its header),
// which leaves one 2 MiB range of 4 KiB pages per kRegion.
//
// A fresh page still costs the kernel's zeroing on its first write: a tenth of
// a 1 M-tet run on our VMs, on the thread that writes it. When the run has
// more than one core, a thread of the command's own (start_heap_populator)
// faults the heap in a few MiB ahead of the highest block operator new handed
// out (MADV_POPULATE_WRITE: as a write would, without writing), so that the
// zeroing happens on another core before the program gets there. It waits
// while the run's own parallel loops use the cores (rdmesh::parallel_regions):
// a refinement lane it preempts would hold up the other at the end of each step.
// For the same reason it runs in the idle scheduling class (SCHED_IDLE): a
// thread of the run that wakes up on its core takes the core at once, rather
// than after the 2 MiB page being faulted in (a few milliseconds on our VMs).
// That let it keep up to 32 MiB ahead (a sixteenth of the heap in use, at
// least 8 MiB), where it kept 8: the refinement's serial pool top-ups of a
// 9.4 M-tet sphere on two threads find more of their pages faulted in (run
// time 18.3-19.7 s against 20.0-20.3 s, alternated).
// It never writes, so what the program reads and computes is the same bits.
//
// Only the command does this: the library leaves the process's allocator to
// its host. Where any step is unavailable (another C library, a sanitizer's
// allocator, THP disabled) the heap simply stays as it was.
#include "heap_setup.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdlib>  // first: defines __GLIBC__ under glibc
#include <new>
#include <thread>

#include "rdmesh/parallel_for.h"

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sched.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

#if defined(__SANITIZE_ADDRESS__)
#define RDMESH_SANITIZED_HEAP 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define RDMESH_SANITIZED_HEAP 1
#endif
#endif

#if defined(__linux__) && defined(__GLIBC__) && !defined(RDMESH_SANITIZED_HEAP)
#define RDMESH_HUGE_PAGE_HEAP 1
#endif

namespace rdmesh::cli {

namespace {
// What the tests read (heap_frontier() and the others); they stay 0 and false
// where the heap setup does not apply.

// The highest end of a block operator new took from the heap: about where
// malloc's free top begins, the next memory to be written.
std::atomic<std::uintptr_t> frontier{0};
// How far the populating thread has faulted the heap in.
std::atomic<std::uintptr_t> populated_end{0};
// The kernel refused MADV_POPULATE_WRITE (before Linux 5.14): the thread stopped.
std::atomic<bool> populate_refused{false};
// The populating thread runs in the idle scheduling class.
std::atomic<bool> populator_idle{false};
}  // namespace

#ifdef RDMESH_HUGE_PAGE_HEAP
namespace {

constexpr std::size_t kRegion = std::size_t{256} << 20;
constexpr std::size_t kMmapThreshold = std::size_t{32} << 20;
constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
constexpr std::uintptr_t kPage = 4096;

// The heap's end as far as it was advised; 0 until setup_heap() ran.
std::atomic<std::uintptr_t> advised_end{0};
// The same end, raised only once the advice was given: as far as the
// populating thread may go (so that it faults huge pages in).
std::atomic<std::uintptr_t> ready_end{0};
// Whether the populating thread was started.
std::atomic<bool> populator_started{false};

/// The populating thread keeps the heap faulted in a sixteenth of the heap in
/// use past the frontier, within these bounds: the pages ahead are resident
/// before the run needs them, so a run's peak grows by as much (32 MiB at most
/// ahead put 25 MB on the peak of a 147 k-tet run, a 52% rise).
constexpr std::uintptr_t kMinAhead = std::uintptr_t{8} << 20;
constexpr std::uintptr_t kMaxAhead = std::uintptr_t{32} << 20;
/// Where the heap began when setup_heap() ran.
std::atomic<std::uintptr_t> heap_start{0};
/// It faults in this much at a time, and sleeps this long when it is ahead.
constexpr std::uintptr_t kStep = kHugePage;
constexpr auto kIdle = std::chrono::milliseconds(1);

#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23  // Linux 5.14
#endif

void raise_to(std::atomic<std::uintptr_t>& mark, std::uintptr_t to) {
  std::uintptr_t seen = mark.load(std::memory_order_relaxed);
  while (to > seen && !mark.compare_exchange_weak(seen, to, std::memory_order_relaxed)) {
  }
}

// The populating thread: faults in the pages of the heap just past the
// frontier before malloc and the program write them, so that the kernel's
// zeroing of fresh pages (a tenth of a large run's time on our VMs) happens on
// another core. MADV_POPULATE_WRITE maps the pages as a write would, without
// writing: it never changes what the program reads. Stops for good if the
// kernel does not know it.
void populate_loop() {
  // Left in the normal class where the kernel refuses: it still waits for the loops.
  const sched_param idle{};
  if (sched_setscheduler(0, SCHED_IDLE, &idle) == 0)  // 0: this thread
    populator_idle.store(true, std::memory_order_relaxed);
  std::uintptr_t done = 0;
  for (;;) {
    const std::uintptr_t heap_end = ready_end.load(std::memory_order_relaxed);
    const std::uintptr_t front = frontier.load(std::memory_order_relaxed) & ~(kHugePage - 1);
    if (done < front) done = front;  // behind the program: it faulted those itself
    const std::uintptr_t in_use =
        front - std::min(front, heap_start.load(std::memory_order_relaxed));
    const std::uintptr_t want =
        std::min(heap_end, front + std::clamp(in_use / 16, kMinAhead, kMaxAhead));
    // No block seen in the heap yet (front 0): nothing to be ahead of. While
    // the run's own threads use the cores (parallel_regions), they fault
    // their pages themselves.
    if (front == 0 || done >= want ||
        rdmesh::parallel_regions().load(std::memory_order_relaxed) > 0) {
      std::this_thread::sleep_for(kIdle);
      continue;
    }
    const std::uintptr_t to = std::min(want, done + kStep);
    if (madvise(reinterpret_cast<void*>(done), to - done, MADV_POPULATE_WRITE) != 0 &&
        errno == EINVAL) {
      populate_refused.store(true, std::memory_order_relaxed);
      return;  // an older kernel
    }
    done = to;
    populated_end.store(done, std::memory_order_relaxed);
  }
}

void advise(std::uintptr_t lo, std::uintptr_t hi) {
  if (hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
}

// After operator new took [at, at + size) from malloc (below the mmap
// ceiling): advises what the heap gained since the last call (from several
// threads at once: one of them advises each new part), and moves the frontier
// when the block lies in the heap (not in another thread's arena).
void after_allocation(std::uintptr_t at, std::size_t size) {
  std::uintptr_t done = advised_end.load(std::memory_order_relaxed);
  if (done == 0) return;
  const auto brk = reinterpret_cast<std::uintptr_t>(sbrk(0));
  // The other threads' arenas are mappings far above the heap's end.
  if (at + size <= brk) raise_to(frontier, at + size);
  const std::uintptr_t end = brk & ~(kHugePage - 1);
  while (end > done) {
    if (advised_end.compare_exchange_weak(done, end, std::memory_order_relaxed)) {
      advise(done, end);
      raise_to(ready_end, end);
      return;
    }
  }
}

}  // namespace
#endif

void setup_heap() {
#ifdef RDMESH_HUGE_PAGE_HEAP
  // Large blocks from the heap rather than from their own mappings (32 MiB is
  // glibc's ceiling for this), the heap never trimmed, and grown by kRegion.
  if (mallopt(M_MMAP_THRESHOLD, static_cast<int>(kMmapThreshold)) != 1) return;
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(std::size_t{1} << 30));
  mallopt(M_TOP_PAD, static_cast<int>(kRegion));
  // One arena: the worker threads allocate from this heap too (their queues
  // and scratch grow there), so they get its huge pages and populating thread,
  // and the peak is this heap's rather than the sum of a heap per thread
  // (1.17 M-tet sphere on two threads: 325 MB with an arena per thread, 303
  // MB with one). The threaded loops reuse their scratch, so the arena's lock
  // is rarely taken.
  mallopt(M_ARENA_MAX, 1);
  const std::uintptr_t before = reinterpret_cast<std::uintptr_t>(sbrk(0));
  // Larger than the heap's free top: the heap grows by it plus the pad. (Held
  // in a volatile, or the compiler may drop the unused allocation.)
  void* volatile probe = std::malloc(std::size_t{4} << 20);
  const std::uintptr_t after = reinterpret_cast<std::uintptr_t>(sbrk(0));
  std::free(probe);
  if (before == static_cast<std::uintptr_t>(-1) || after <= before) return;
  const std::uintptr_t lo = (before + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t hi = after & ~(kHugePage - 1);
  advise(lo, hi);
  heap_start.store(lo, std::memory_order_relaxed);
  advised_end.store(hi, std::memory_order_relaxed);
  ready_end.store(hi, std::memory_order_relaxed);
#endif
}

std::uintptr_t heap_frontier() { return frontier.load(std::memory_order_relaxed); }
std::uintptr_t heap_populated_end() { return populated_end.load(std::memory_order_relaxed); }
bool heap_populator_refused() { return populate_refused.load(std::memory_order_relaxed); }
bool heap_populator_idle() { return populator_idle.load(std::memory_order_relaxed); }

void start_heap_populator() {
#ifdef RDMESH_HUGE_PAGE_HEAP
  if (advised_end.load(std::memory_order_relaxed) == 0) return;  // setup_heap() did not apply
  if (populator_started.exchange(true, std::memory_order_relaxed)) return;  // running already
  std::thread(populate_loop).detach();
#endif
}

}  // namespace rdmesh::cli

#ifdef RDMESH_HUGE_PAGE_HEAP
// The replaced operator new: glibc's malloc, then the advice. (The standard
// library's operator delete calls free, its array and nothrow forms call this
// one; the aligned forms are left to it.)
void* operator new(std::size_t size) {
  if (size == 0) size = 1;
  void* p;
  while ((p = std::malloc(size)) == nullptr) {
    const std::new_handler handler = std::get_new_handler();
    if (handler == nullptr) throw std::bad_alloc();
    handler();
  }
  if (size >= rdmesh::cli::kMmapThreshold) {  // its own mapping, written from its first page
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    rdmesh::cli::advise(at & ~(rdmesh::cli::kPage - 1),
                        (at + size + rdmesh::cli::kPage - 1) & ~(rdmesh::cli::kPage - 1));
  } else {
    rdmesh::cli::after_allocation(reinterpret_cast<std::uintptr_t>(p), size);
  }
  return p;
}
#endif
