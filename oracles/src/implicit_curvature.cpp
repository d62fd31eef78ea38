// ImplicitOracle::curvature: principal curvatures of a level set from the
// function's gradient and Hessian (finite differences), for sizes by curvature.
#include <algorithm>
#include <cmath>

#include "rdmesh/implicit_oracle.h"

namespace rdmesh {

std::optional<double> ImplicitOracle::curvature(const Point3& p, PatchId patch) const {
  if (patch.value <= 0 || patch.value >= static_cast<int>(key_of_patch_.size()) || !is_finite(p)) {
    return std::nullopt;
  }
  const int n_functions = static_cast<int>(functions_.size());
  const int k = key_of_patch_[patch.value] % (n_functions + 1);
  if (k == n_functions) return 0.0;  // the box's faces are planes
  const Function& f = functions_[k];
  const double h = 1e-4 * box_.diagonal();
  const Point3 axis[3] = {{h, 0, 0}, {0, h, 0}, {0, 0, h}};
  // p may lie off the zero set (a chord's point): a few Newton steps along the
  // gradient bring it onto it, whose curvature is asked, not that of the level
  // set through p (a torus's minor radius 0.3 read 0.27 from 0.03 inside).
  Point3 x = p;
  for (int it = 0; it < 4; ++it) {
    const double v = f(x);
    const Point3 grad{(f(x + axis[0]) - f(x - axis[0])) / (2 * h),
                      (f(x + axis[1]) - f(x - axis[1])) / (2 * h),
                      (f(x + axis[2]) - f(x - axis[2])) / (2 * h)};
    const double gg = squared_norm(grad);
    if (!(gg > 0) || !std::isfinite(v) || !std::isfinite(gg)) break;
    const Point3 step = (v / gg) * grad;
    if (!(norm(step) < 0.1 * box_.diagonal())) break;
    x = x - step;
    if (norm(step) <= h) break;
  }
  const double f0 = f(x);
  double g[3], hess[3][3];
  for (int i = 0; i < 3; ++i) {
    const double fp = f(x + axis[i]), fm = f(x - axis[i]);
    g[i] = (fp - fm) / (2 * h);
    hess[i][i] = (fp - 2 * f0 + fm) / (h * h);
    for (int j = 0; j < i; ++j) {
      const double d = f(x + axis[i] + axis[j]) - f(x + axis[i] - axis[j]) -
                       f(x - axis[i] + axis[j]) + f(x - axis[i] - axis[j]);
      hess[i][j] = hess[j][i] = d / (4 * h * h);
    }
  }
  const double gg = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  if (!(gg > 0) || !std::isfinite(gg) || !std::isfinite(f0)) return std::nullopt;
  // M = P H P / |g| with P = I - n n^T: its eigenvalues are 0 (along n) and
  // the principal curvatures k1, k2, so trace(M) = k1 + k2 and the sum of its
  // principal 2x2 minors is k1 k2.
  const double n[3] = {g[0] / gg, g[1] / gg, g[2] / gg};
  double proj[3][3], hp[3][3], m[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) proj[i][j] = (i == j ? 1.0 : 0.0) - n[i] * n[j];
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      hp[i][j] = 0;
      for (int l = 0; l < 3; ++l) hp[i][j] += hess[i][l] * proj[l][j];
    }
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      m[i][j] = 0;
      for (int l = 0; l < 3; ++l) m[i][j] += proj[i][l] * hp[l][j];
      m[i][j] /= gg;
    }
  }
  const double trace = m[0][0] + m[1][1] + m[2][2];
  const double product = m[0][0] * m[1][1] - m[0][1] * m[1][0] + m[0][0] * m[2][2] -
                         m[0][2] * m[2][0] + m[1][1] * m[2][2] - m[1][2] * m[2][1];
  const double half = 0.5 * trace;
  const double result = std::fabs(half) + std::sqrt(std::max(0.0, half * half - product));
  if (!std::isfinite(result)) return std::nullopt;
  return result;
}

}  // namespace rdmesh
