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

// Whether this kernel takes the advice at all (THP compiled in).
bool kernel_takes_advice() {
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

}  // namespace
}  // namespace rdmesh::cli
