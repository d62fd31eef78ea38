// portable_acos: close to the true arc cosine over the whole range, exact at
// the ends, and the same bits as the formula it is made of (no libm inside).
#include "rdmesh/portable_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace {

/// Distance in units in the last place between two positive doubles.
std::int64_t ulps(double a, double b) {
  std::int64_t ia = 0, ib = 0;
  std::memcpy(&ia, &a, sizeof a);
  std::memcpy(&ib, &b, sizeof b);
  return ia > ib ? ia - ib : ib - ia;
}

TEST(PortableAcos, WithinTwoUlpsOfLibmOverTheRange) {
  // 2 million arguments spread over [-1, 1], denser near +-1 where acos is steep.
  std::int64_t worst = 0;
  for (int i = 0; i <= 2000000; ++i) {
    const double t = -1.0 + 2.0 * i / 2000000.0;
    for (const double x : {t, std::copysign(1.0 - std::ldexp(1.0 - std::abs(t), -20), t)}) {
      const double ours = rdmesh::portable_acos(x), libm = std::acos(x);
      const std::int64_t d = ulps(ours, libm);
      if (d > worst) worst = d;
      ASSERT_LE(d, 2) << "x = " << x << ": " << ours << " against " << libm;
    }
  }
  EXPECT_GE(worst, 0);
}

TEST(PortableAcos, KnownValuesAndEnds) {
  const double pi = 3.141592653589793116;
  EXPECT_EQ(rdmesh::portable_acos(1.0), 0.0);
  EXPECT_EQ(rdmesh::portable_acos(-1.0), pi);
  EXPECT_EQ(rdmesh::portable_acos(1.5), 0.0);  // clamped
  EXPECT_EQ(rdmesh::portable_acos(-7.0), pi);
  EXPECT_TRUE(std::isnan(rdmesh::portable_acos(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_LE(ulps(rdmesh::portable_acos(0.0), pi / 2), 1);
  EXPECT_LE(ulps(rdmesh::portable_acos(0.5), pi / 3), 1);
  EXPECT_LE(ulps(rdmesh::portable_acos(-0.5), 2 * pi / 3), 1);
  EXPECT_LE(ulps(rdmesh::portable_acos(std::sqrt(0.5)), pi / 4), 1);
  // Near 1 the angle is sqrt(2 (1 - x)) to first order: relative accuracy kept.
  const double x = 1.0 - 0x1p-40;
  EXPECT_LE(ulps(rdmesh::portable_acos(x), std::acos(x)), 2);
}

TEST(PortableAcos, DecreasingAcrossTheBranchSeams) {
  // The three formulas meet at -1/2 and 1/2: no step backwards there.
  for (const double seam : {-0.5, 0.5}) {
    double x = seam;
    for (int k = 0; k < 8; ++k) x = std::nextafter(x, -2.0);
    double previous = rdmesh::portable_acos(x);
    for (int k = 0; k < 16; ++k) {
      x = std::nextafter(x, 2.0);
      const double a = rdmesh::portable_acos(x);
      EXPECT_LE(a, previous) << "at " << x;
      previous = a;
    }
  }
}

}  // namespace
