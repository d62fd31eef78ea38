// SizeCaps, the protecting-ball planner's caps per curve: its windowed queries
// give what a scan over every cap gives, bit for bit, on open and closed curves.
#include "size_caps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <vector>

namespace rdmesh::detail {
namespace {

struct Brute {
  std::vector<SizeCaps::Cap> caps;
  double lowest_at(double x, double growth) const {
    double now = HUGE_VAL;
    for (const auto& c : caps) now = std::min(now, c.value + growth * std::fabs(c.arc - x));
    return now;
  }
};

TEST(SizeCaps, LowestAtEqualsTheMinimumOverEveryCap) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> arc(0, 100), value(0.01, 5);
  SizeCaps caps;
  Brute brute;
  EXPECT_EQ(caps.lowest_at(3, 0.5), HUGE_VAL);
  for (int i = 0; i < 400; ++i) {
    const double a = i % 50 == 0 ? 42.0 : arc(rng);  // some equal arcs too
    const double v = value(rng);
    caps.add(a, v);
    brute.caps.push_back({a, v});
    for (int q = 0; q < 5; ++q) {
      const double x = arc(rng) * 1.1 - 5;
      ASSERT_EQ(caps.lowest_at(x, 0.5), brute.lowest_at(x, 0.5)) << "x " << x;
    }
  }
  EXPECT_EQ(caps.size(), 400u);
}

TEST(SizeCaps, ForEachNearVisitsEveryCapWithinReachAroundTheClosingPoint) {
  std::mt19937 rng(8);
  const double length = 10;
  std::uniform_real_distribution<double> arc(0, length), reach(0.01, 6);
  SizeCaps caps;
  std::vector<double> arcs;
  for (int i = 0; i < 300; ++i) {
    arcs.push_back(arc(rng));
    caps.add(arcs.back(), 1);
  }
  for (bool closed : {false, true}) {
    for (int q = 0; q < 500; ++q) {
      const double a = arc(rng), r = reach(rng);
      std::multiset<double> seen;
      caps.for_each_near(a, r, closed, length, [&](const SizeCaps::Cap& c) { seen.insert(c.arc); });
      for (double x : arcs) {
        double d = std::fabs(x - a);
        if (closed) d = std::min(d, length - d);
        if (d <= r) {
          EXPECT_TRUE(seen.count(x)) << "arc " << x << " from " << a << " reach " << r;
        }
      }
      if (!closed) {
        // An open curve's window is exactly [a - r, a + r].
        for (double x : seen) {
          EXPECT_LE(std::fabs(x - a), r);
        }
      }
    }
  }
}

}  // namespace
}  // namespace rdmesh::detail
