// portable_acos: within 2 ulps of glibc's acos over the whole range, exact at
// the ends and at known angles, clamped outside [-1, 1], monotone at its seams.
#include "rdmesh/portable_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>

namespace {

/// Distance in units in the last place between two positive doubles.
std::int64_t ulps(double a, double b) {
  std::int64_t ia = 0, ib = 0;
  std::memcpy(&ia, &a, sizeof a);
  std::memcpy(&ib, &b, sizeof b);
  return ia > ib ? ia - ib : ib - ia;
}

TEST(PortableAcos, WithinTwoUlpsOfLibmOverTheRange) {
  // 4 million arguments: 2 million spread over [-1, 1], and as many within
  // 2^-20 of +-1, where acos is steep.
  for (int i = 0; i <= 2000000; ++i) {
    const double t = -1.0 + 2.0 * i / 2000000.0;
    for (const double x : {t, std::copysign(1.0 - std::ldexp(1.0 - std::abs(t), -20), t)}) {
      const double ours = rdmesh::portable_acos(x), libm = std::acos(x);
      ASSERT_LE(ulps(ours, libm), 2) << "x = " << x << ": " << ours << " against " << libm;
    }
  }
}

TEST(PortableAcos, KnownValuesAndEnds) {
  constexpr double pi = std::numbers::pi;
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
