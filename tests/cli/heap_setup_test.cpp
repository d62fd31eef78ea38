// The command's heap (cli/heap_setup.cpp): after setup_heap(), the heap is
// advised for transparent huge pages as it grows, far past its first region,
// and blocks above glibc's mmap ceiling are advised whole. The test binary
// links heap_setup.cpp, so it runs with the command's operator new.
#include "heap_setup.h"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "rdmesh/parallel_for.h"

#if defined(__SANITIZE_ADDRESS__)
#define RDMESH_TEST_SANITIZED_HEAP 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define RDMESH_TEST_SANITIZED_HEAP 1
#endif
#endif

namespace rdmesh::cli {
namespace {

// Bytes of [lo, hi) in mappings with the VmFlag "hg" (MADV_HUGEPAGE).
std::uintptr_t advised_bytes(std::uintptr_t lo, std::uintptr_t hi) {
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  std::uintptr_t from = 0, to = 0, total = 0;
  while (std::getline(smaps, line)) {
    std::uintptr_t a = 0, b = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> a >> dash >> b && dash == '-') {
      from = a, to = b;
    } else if (line.rfind("VmFlags:", 0) == 0 && (line + " ").find(" hg ") != std::string::npos) {
      const std::uintptr_t x = std::max(from, lo), y = std::min(to, hi);
      if (y > x) total += y - x;
    }
  }
  return total;
}

// Whether this kernel takes the advice at all (THP compiled in). Unused
// under a sanitizer, whose allocator the heap setup leaves alone.
[[maybe_unused]] bool kernel_takes_advice() {
  void* p = mmap(nullptr, 4 << 20, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) return false;
  const bool ok = madvise(p, 4 << 20, MADV_HUGEPAGE) == 0;
  munmap(p, 4 << 20);
  return ok;
}

TEST(HeapSetup, TheHeapIsAdvisedForHugePagesAsItGrows) {
  const auto start = reinterpret_cast<std::uintptr_t>(sbrk(0));
  setup_heap();
  std::vector<std::unique_ptr<char[]>> blocks;  // 640 MB of address space, never written
  for (int i = 0; i < 160; ++i) blocks.emplace_back(new char[std::size_t{4} << 20]);
  std::unique_ptr<char[]> big(new char[std::size_t{40} << 20]);  // its own mapping
  const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0));
  const auto big_at = reinterpret_cast<std::uintptr_t>(big.get());
#if defined(__linux__) && defined(__GLIBC__) && !defined(RDMESH_TEST_SANITIZED_HEAP)
  ASSERT_GE(end - start, std::uintptr_t{600} << 20) << "the blocks did not come from the heap";
  if (kernel_takes_advice()) {
    // All but the 2 MiB range holding the header of the block that grew the
    // heap, per 256 MiB region, and the unaligned ends.
    EXPECT_GE(advised_bytes(start, end), end - start - (std::uintptr_t{12} << 20));
    EXPECT_GE(advised_bytes(big_at, big_at + (std::uintptr_t{40} << 20)), std::uintptr_t{40} << 20);
  } else {
    EXPECT_EQ(advised_bytes(0, UINTPTR_MAX), 0u);
  }
#else
  // Under a sanitizer's allocator (or another C library) the heap is left alone.
  EXPECT_EQ(advised_bytes(0, UINTPTR_MAX), 0u);
  (void)start, (void)end, (void)big_at;
#endif
}

// Pages of [lo, hi) (page-aligned) that are resident (mincore).
[[maybe_unused]] std::size_t resident_pages(std::uintptr_t lo, std::uintptr_t hi) {
  const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  std::vector<unsigned char> in((hi - lo) / page);
  if (mincore(reinterpret_cast<void*>(lo), hi - lo, in.data()) != 0) return 0;
  std::size_t n = 0;
  for (const unsigned char b : in) n += b & 1;
  return n;
}

TEST(HeapSetup, ThePopulatorFaultsTheHeapInAheadOfTheProgram) {
  setup_heap();
  std::unique_ptr<char[]> one(new char[std::size_t{1} << 20]);  // from the free top: a frontier
  char* volatile kept = one.get();  // (or the compiler may leave the allocation out)
  (void)kept;
  const std::uintptr_t huge = std::uintptr_t{2} << 20;
  // 4 MiB just ahead of where the next blocks go, past the page holding the
  // free top's header: nothing wrote them yet.
  const std::uintptr_t lo = ((heap_frontier() + huge - 1) & ~(huge - 1)) + huge;
  const std::uintptr_t hi = lo + (std::uintptr_t{4} << 20);
#if defined(__linux__) && defined(__GLIBC__) && !defined(RDMESH_TEST_SANITIZED_HEAP)
  ASSERT_GT(heap_frontier(), 0u);
  ASSERT_LE(hi, reinterpret_cast<std::uintptr_t>(sbrk(0))) << "the heap ends before the window";
  // (A stray small block of the test's own may have landed there.)
  EXPECT_LE(resident_pages(lo, hi), 16u) << "the window was faulted in before the populator ran";
  start_heap_populator();
  // Waits for the thread (it runs on its own; the test does not time it).
  for (int i = 0; i < 20000 && heap_populated_end() < hi && !heap_populator_refused(); ++i)
    usleep(1000);
  if (heap_populator_refused()) {
    // A kernel before 5.14 has no MADV_POPULATE_WRITE: the heap stays as it was.
    EXPECT_LE(resident_pages(lo, hi), 16u);
  } else {
    ASSERT_GE(heap_populated_end(), hi) << "the populator did not get ahead of the frontier";
    const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    EXPECT_EQ(resident_pages(lo, hi), (hi - lo) / page);
    // It yields its core at once to a thread of the run (SCHED_IDLE needs no privilege).
    EXPECT_TRUE(heap_populator_idle());
  }
#else
  // Under a sanitizer's allocator the command's heap setup does not apply.
  start_heap_populator();
  EXPECT_EQ(heap_frontier(), 0u);
  EXPECT_EQ(heap_populated_end(), 0u);
  (void)lo, (void)hi;
#endif
}

TEST(HeapSetup, ThePopulatorWaitsWhileParallelLoopsHoldTheCores) {
  setup_heap();
  std::unique_ptr<char[]> one(new char[std::size_t{1} << 20]);  // a frontier, as above
  char* volatile kept = one.get();
  (void)kept;
  const std::uintptr_t huge = std::uintptr_t{2} << 20;
  const std::uintptr_t hi = ((heap_frontier() + huge - 1) & ~(huge - 1)) + 3 * huge;
#if defined(__linux__) && defined(__GLIBC__) && !defined(RDMESH_TEST_SANITIZED_HEAP)
  ASSERT_GT(heap_frontier(), 0u);
  // Started inside a loop on two threads, it faults nothing in until the loop
  // ends (it would need a few milliseconds for these pages).
  bool idle_in_loop = false;
  parallel_tasks(2, 2, [&](std::size_t task) {
    if (task != 0) return;
    start_heap_populator();
    usleep(200000);
    idle_in_loop = heap_populated_end() == 0;
  });
  EXPECT_TRUE(idle_in_loop) << "the populator ran while both threads were busy";
  for (int i = 0; i < 20000 && heap_populated_end() < hi && !heap_populator_refused(); ++i)
    usleep(1000);
  if (!heap_populator_refused()) {
    EXPECT_GE(heap_populated_end(), hi) << "the populator did not go on after the loop";
  }
#else
  (void)hi;
#endif
}

}  // namespace
}  // namespace rdmesh::cli
