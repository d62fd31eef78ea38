// ImplicitOracle::project: closest points on a patch, used to measure the
// output's distance to the surface. Candidates: the foot point on each
// function's zero set, and on each crease where two functions vanish; each is
// verified by the labels around it, the closest verified one wins.
#include <cmath>
#include <string>

#include "rdmesh/errors.h"
#include "rdmesh/implicit_oracle.h"

namespace rdmesh {

std::optional<Point3> ImplicitOracle::project_on_function(const Point3& p, int k, int a,
                                                          int b) const {
  const Function& f = functions_[k];
  const double max_step = 0.25 * box_.diagonal();
  // Newton along the gradient onto the zero set of f, from r.
  auto newton = [&](Point3 q) -> std::optional<Point3> {
    for (int it = 0; it < 60; ++it) {
      const double v = f(q);
      const Point3 g = gradient(k, q);
      const double gg = squared_norm(g);
      if (!(gg > 0) || !std::isfinite(v)) return std::nullopt;
      Point3 step = (v / gg) * g;
      const double len = norm(step);
      if (len > max_step) step = (max_step / len) * step;
      q = q - step;
      if (len <= 0.05 * tolerance_) return q;
    }
    return std::nullopt;
  };
  std::optional<Point3> q = newton(p);
  // Foot-point iteration: project p on the tangent plane at q, back onto the surface.
  for (int it = 0; q && it < 200; ++it) {
    Point3 n = gradient(k, *q);
    const double nn = norm(n);
    if (!(nn > 0)) return std::nullopt;
    n = (1 / nn) * n;
    const Point3 r = p - dot(p - *q, n) * n;
    std::optional<Point3> next = newton(r);
    if (!next) return std::nullopt;
    const double moved = distance(*next, *q);
    q = next;
    if (moved <= tolerance_) break;
  }
  if (!q || !box_.contains(*q)) return std::nullopt;
  // Verify: the labels on both sides along the normal are the patch's sides.
  Point3 n = gradient(k, *q);
  const double nn = norm(n);
  if (!(nn > 0)) return std::nullopt;
  const double probe = 100 * tolerance_ / nn;
  const int l1 = locate(*q - probe * n).label.value, l2 = locate(*q + probe * n).label.value;
  if (std::min(l1, l2) != a || std::max(l1, l2) != b) return std::nullopt;
  return q;
}

std::optional<Point3> ImplicitOracle::project(const Point3& p, PatchId patch) const {
  if (patch.value <= 0 || patch.value >= static_cast<int>(key_of_patch_.size()) || !is_finite(p)) {
    return std::nullopt;
  }
  const int key = key_of_patch_[patch.value];
  const int n_functions = static_cast<int>(functions_.size());
  const int k = key % (n_functions + 1);
  if (k == n_functions) return std::nullopt;  // a boundary on the box: no function carries it
  int a = -1, b = -1;
  for (const PatchInfo& info : patches_) {
    if (info.id == patch) a = info.side_a.value, b = info.side_b.value;
  }
  std::optional<Point3> best = project_on_function(p, k, a, b);
  // The closest point of a patch may lie on its boundary, a crease where f_k
  // and another function vanish (a cylinder's rim): project on those curves too.
  for (int j : used_) {
    if (j == k) continue;
    const std::optional<Point3> q = project_on_crease(p, k, j, a, b);
    if (q && (!best || distance(*q, p) < distance(*best, p))) best = q;
  }
  return best;
}

std::optional<Point3> ImplicitOracle::project_on_crease(const Point3& p, int k, int l, int a,
                                                        int b) const {
  const Function& f = functions_[k];
  const Function& g = functions_[l];
  const double max_step = 0.25 * box_.diagonal();
  // Gauss-Newton onto {f = 0, g = 0}: the least-norm step solving the linearized system.
  auto newton = [&](Point3 q) -> std::optional<Point3> {
    for (int it = 0; it < 60; ++it) {
      const double fv = f(q), gv = g(q);
      const Point3 gf = gradient(k, q), gg = gradient(l, q);
      const double a11 = dot(gf, gf), a12 = dot(gf, gg), a22 = dot(gg, gg);
      const double det = a11 * a22 - a12 * a12;
      if (!(det > 1e-12 * a11 * a22) || !std::isfinite(fv) || !std::isfinite(gv)) {
        return std::nullopt;  // tangent surfaces or no crease here
      }
      const double l1 = (a22 * fv - a12 * gv) / det, l2 = (a11 * gv - a12 * fv) / det;
      Point3 step = l1 * gf + l2 * gg;
      const double len = norm(step);
      if (len > max_step) step = (max_step / len) * step;
      q = q - step;
      if (len <= 0.05 * tolerance_) return q;
    }
    return std::nullopt;
  };
  std::optional<Point3> q = newton(p);
  // Foot-point iteration along the crease's tangent.
  for (int it = 0; q && it < 200; ++it) {
    Point3 t = cross(gradient(k, *q), gradient(l, *q));
    const double tt = norm(t);
    if (!(tt > 0)) return std::nullopt;
    t = (1 / tt) * t;
    const std::optional<Point3> next = newton(*q + dot(p - *q, t) * t);
    if (!next) return std::nullopt;
    const double moved = distance(*next, *q);
    q = next;
    if (moved <= tolerance_) break;
  }
  if (!q || !box_.contains(*q)) return std::nullopt;
  // Verify: the four quadrants around the crease show both sides of the patch.
  Point3 u = gradient(k, *q), w = gradient(l, *q);
  u = (1 / norm(u)) * u;
  w = (1 / norm(w)) * w;
  const double probe = 100 * tolerance_;
  bool seen_a = false, seen_b = false;
  for (double su : {-1.0, 1.0}) {
    for (double sw : {-1.0, 1.0}) {
      const int label = locate(*q + (probe * su) * u + (probe * sw) * w).label.value;
      seen_a = seen_a || label == a;
      seen_b = seen_b || label == b;
    }
  }
  if (!seen_a || !seen_b) return std::nullopt;
  return q;
}

}  // namespace rdmesh
