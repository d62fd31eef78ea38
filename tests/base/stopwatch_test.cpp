// The stopwatch every phase's time comes from: never negative, and lap() starts
// the next phase where the last one ended (no time is lost between phases).
#include "rdmesh/stopwatch.h"

#include <gtest/gtest.h>

namespace rdmesh {
namespace {

TEST(Stopwatch, LapsAddUpToTheTotal) {
  const Stopwatch total;
  Stopwatch phase;
  double sum = 0;
  volatile double sink = 0;
  for (int i = 0; i < 5; ++i) {
    for (int k = 0; k < 100000; ++k) sink = sink + k;
    const double lap = phase.lap();
    EXPECT_GE(lap, 0);
    sum += lap;
  }
  const double all = total.seconds();
  EXPECT_LE(sum, all);
  EXPECT_GE(phase.seconds(), 0);
  phase.restart();
  EXPECT_LE(phase.seconds(), total.seconds());
}

}  // namespace
}  // namespace rdmesh
