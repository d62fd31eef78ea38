// portable_acos: acos from +, -, *, / and sqrt only (portable_math.h says why).
// This file is compiled with -ffp-contract=off (base/CMakeLists.txt): a fused
// multiply-add rounds once where the two operations round twice, so letting
// the compiler fuse them would make the bits depend on the target again.
#include "rdmesh/portable_math.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>

namespace rdmesh {
namespace {

/// Taylor coefficients of asin(s) = sum_n c_n s^(2n+1), c_n = (2n)! / (4^n (n!)^2 (2n + 1)),
/// folded by the compiler. For |s| <= 1/2 (s^2 <= 1/4) the first term left out,
/// n = 28, is below 1e-19 |s|: far below half a unit in the last place of asin(s).
constexpr std::size_t kAsinTerms = 28;

constexpr std::array<double, kAsinTerms> asin_coefficients() {
  std::array<double, kAsinTerms> c{};
  double central = 1.0;  // (2n)! / (4^n (n!)^2), from the one before
  for (std::size_t n = 0; n < kAsinTerms; ++n) {
    if (n > 0) central *= static_cast<double>(2 * n - 1) / static_cast<double>(2 * n);
    c[n] = central / static_cast<double>(2 * n + 1);
  }
  return c;
}

constexpr std::array<double, kAsinTerms> kAsin = asin_coefficients();

/// asin(s) for |s| <= 1/2: s + s^3 (c_1 + s^2 (c_2 + ...)), by Horner from the last term.
double asin_small(double s) {
  const double z = s * s;
  double p = kAsin[kAsinTerms - 1];
  for (std::size_t n = kAsinTerms - 1; n-- > 1;) p = p * z + kAsin[n];
  return s + s * z * p;
}

}  // namespace

double portable_acos(double x) {
  if (std::isnan(x)) return x;
  if (x >= 1.0) return 0.0;
  if (x <= -1.0) return std::numbers::pi;
  // acos x = 2 asin sqrt((1 - x) / 2), where 1 - x (x in (1/2, 1)) and the halving are exact.
  if (x > 0.5) return 2.0 * asin_small(std::sqrt(0.5 * (1.0 - x)));
  if (x < -0.5) return std::numbers::pi - 2.0 * asin_small(std::sqrt(0.5 * (1.0 + x)));
  return std::numbers::pi / 2 - asin_small(x);
}

}  // namespace rdmesh
