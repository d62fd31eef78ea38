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
//  - every time the heap has grown, the new part is advised MADV_HUGEPAGE. The
//    command replaces the global operator new for this (allowed to a program,
//    not to a library): after each allocation it compares the heap's end with
//    what it advised already, which costs a comparison, and a block above the
//    ceiling (its own mapping) is advised whole.
// A region is advised before the blocks in it are written, except the first
// page of the block whose allocation grew the heap (malloc writes its header),
// which leaves one 2 MiB range of 4 KiB pages per kRegion.
//
// Only the command does this: the library leaves the process's allocator to
// its host. Where any step is unavailable (another C library, a sanitizer's
// allocator, THP disabled) the heap simply stays as it was.
#include "heap_setup.h"

#include <atomic>
#include <cstdint>
#include <cstdlib>  // first: defines __GLIBC__ under glibc
#include <new>

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
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

#ifdef RDMESH_HUGE_PAGE_HEAP
namespace {

constexpr std::size_t kRegion = std::size_t{256} << 20;
constexpr std::size_t kMmapThreshold = std::size_t{32} << 20;
constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
constexpr std::uintptr_t kPage = 4096;

// The heap's end as far as it was advised; 0 until setup_heap() ran.
std::atomic<std::uintptr_t> advised_end{0};

void advise(std::uintptr_t lo, std::uintptr_t hi) {
  if (hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
}

// Advises what the heap gained since the last call (from several threads at
// once: one of them advises each new part).
void advise_heap_growth() {
  std::uintptr_t done = advised_end.load(std::memory_order_relaxed);
  if (done == 0) return;
  const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(sbrk(0)) & ~(kHugePage - 1);
  while (end > done) {
    if (advised_end.compare_exchange_weak(done, end, std::memory_order_relaxed)) {
      advise(done, end);
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
  advised_end.store(hi, std::memory_order_relaxed);
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
    rdmesh::cli::advise_heap_growth();
  }
  return p;
}
#endif
