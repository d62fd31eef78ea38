// The command's heap: one large region backed by transparent huge pages.
//
// A run allocates its memory in many small steps (OpenCASCADE's shapes while
// reading, the triangulation's cell blocks while refining), and on the shared
// virtual machines we measure on every fresh 4 KiB page costs a fault: 6-10%
// of a CAD run. Huge pages take 512 times fewer. glibc only asks for them when
// told to (the glibc.malloc.hugetlb tunable, an environment variable read at
// process start), so the command does the same by hand: the heap grows once by
// kRegion, which is advised MADV_HUGEPAGE, large blocks come from the heap too,
// and freed memory stays there for reuse (a restart of refinement allocates a
// new triangulation of about the old one's size).
//
// Only the command does this: the library leaves the process's allocator to
// its host. Where any step is unavailable (another C library, a sanitizer's
// allocator, THP disabled) the heap simply stays as it was.
#include "heap_setup.h"

#include <cstdint>
#include <cstdlib>  // first: defines __GLIBC__ under glibc

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace rdmesh::cli {

#if defined(__SANITIZE_ADDRESS__)
#define RDMESH_SANITIZED_HEAP 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define RDMESH_SANITIZED_HEAP 1
#endif
#endif

void setup_heap() {
#if defined(__linux__) && defined(__GLIBC__) && !defined(RDMESH_SANITIZED_HEAP)
  constexpr std::size_t kRegion = std::size_t{256} << 20;
  constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
  // Large blocks from the heap rather than from their own mappings (32 MiB is
  // glibc's ceiling for this), the heap never trimmed, and grown by kRegion.
  if (mallopt(M_MMAP_THRESHOLD, 32 << 20) != 1) return;
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
  if (hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
#endif
}

}  // namespace rdmesh::cli
