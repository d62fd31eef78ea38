// intersect() is the mesher's hot path: it must not allocate. This file replaces
// the global operator new of the test executable to count allocations.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <random>

#include "rdmesh/domain_file.h"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return ::operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace rdmesh {
namespace {

TEST(ImplicitOracleHotPath, IntersectAndLocateDoNotAllocate) {
  const LoadedDomain d = parse_domain_json(R"({"bbox": [-1.5, -1.5, -1.5, 1.5, 1.5, 1.5],
      "functions": {"outer": "x^2 + y^2 + z^2 - 1", "inner": "(x-0.1)^2 + y^2 + z^2 - 0.2"},
      "subdomains": [{"inside": ["outer"], "outside": ["inner"]}, {"inside": ["inner"]}]})",
                                           "alloc.json");
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::vector<Point3> points(2000);
  for (Point3& p : points) p = {u(rng), u(rng), u(rng)};
  d.oracle->intersect(points[0], points[1]);  // first call on this thread compiles
  const long before = g_allocations.load();
  int hits = 0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    hits += d.oracle->intersect(points[i], points[i + 1]).has_value();
    hits += d.oracle->locate(points[i]).label.value > 3;
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_GT(hits, 100);
  // The counter works: a vector allocates.
  std::vector<int>* v = new std::vector<int>(3);
  EXPECT_GT(g_allocations.load() - before, 0);
  delete v;
}

}  // namespace
}  // namespace rdmesh
