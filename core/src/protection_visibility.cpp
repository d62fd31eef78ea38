// The last step of the protection plan: no protecting ball may be hidden in
// the regular triangulation.
//
// A weighted point (p, w_p) whose centre lies in its own power cell is a
// vertex of the regular triangulation: its power to itself, -w_p, must not
// exceed its power to any other ball, |p - q|^2 - w_q. So it is enough that
// for every pair, |p - q|^2 >= w_q - w_p (the larger ball's weight minus the
// smaller one's). The planner's rules B1/B2 give that almost everywhere; where
// features lie closer than the minimum size (edges of touching solids that the
// general fuse did not merge, curves shorter than the minimum size), the
// unresolved pairs are cut to tiny balls, and a larger unrelated ball around
// them (a corner's) would hide them. Cutting the larger ball to
// sqrt(|p - q|^2 + w_p) restores the inequality; a cut can expose the cut ball
// to a still larger one, so the pass repeats until nothing changes. Radii only
// decrease, so it ends.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include "protection.h"
#include "simplex_geometry.h"

namespace rdmesh::detail {
namespace {

struct VisibleBall {
  Point3 center;
  double radius;
  BallRef ref;
};

/// Calls visit(i, j) for every pair of balls whose centres are closer than
/// the larger radius (the only pairs where one can hide the other).
template <class Visit>
void for_each_covering_pair(const std::vector<VisibleBall>& balls, Visit&& visit) {
  std::vector<double> radii;
  for (const VisibleBall& b : balls) radii.push_back(b.radius);
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  const double cell = std::max(2 * radii[radii.size() / 2], 1e-300);
  auto coord = [cell](double x) { return static_cast<std::int64_t>(std::floor(x / cell)); };
  auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
    return (static_cast<std::uint64_t>(x & 0x1fffff) << 42) |
           (static_cast<std::uint64_t>(y & 0x1fffff) << 21) |
           static_cast<std::uint64_t>(z & 0x1fffff);
  };
  std::unordered_map<std::uint64_t, std::vector<int>> grid;
  for (std::size_t k = 0; k < balls.size(); ++k) {
    const Point3& c = balls[k].center;
    grid[key(coord(c.x), coord(c.y), coord(c.z))].push_back(static_cast<int>(k));
  }
  for (std::size_t k = 0; k < balls.size(); ++k) {
    const VisibleBall& big = balls[k];
    auto test = [&](int other) {
      if (other == static_cast<int>(k)) return;
      const VisibleBall& small = balls[other];
      // Each pair from its larger ball (ties: from the first).
      if (small.radius > big.radius || (small.radius == big.radius && other < static_cast<int>(k)))
        return;
      if (distance(big.center, small.center) < big.radius) visit(static_cast<int>(k), other);
    };
    const std::int64_t span = static_cast<std::int64_t>(std::ceil(big.radius / cell));
    if (std::pow(2.0 * span + 1, 3) > static_cast<double>(balls.size())) {
      for (std::size_t o = 0; o < balls.size(); ++o) test(static_cast<int>(o));
      continue;
    }
    const std::int64_t cx = coord(big.center.x), cy = coord(big.center.y), cz = coord(big.center.z);
    for (std::int64_t x = cx - span; x <= cx + span; ++x) {
      for (std::int64_t y = cy - span; y <= cy + span; ++y) {
        for (std::int64_t z = cz - span; z <= cz + span; ++z) {
          auto cell_balls = grid.find(key(x, y, z));
          if (cell_balls == grid.end()) continue;
          for (int other : cell_balls->second) test(other);
        }
      }
    }
  }
}

}  // namespace

void ProtectionPlanner::keep_all_visible() {
  for (int round = 0; round < 100; ++round) {
    std::vector<VisibleBall> balls;
    for (std::size_t q = 0; q < corners_.size(); ++q) {
      balls.push_back({corners_[q].point, corner_radius_[q], BallRef{-1, 0, static_cast<int>(q)}});
    }
    for (std::size_t j = 0; j < curves_.size(); ++j) {
      const std::vector<BallSample>& s = curves_[j].samples;
      const std::size_t first = curves_[j].c.info.closed ? 0 : 1;
      for (std::size_t i = first; i + 1 < s.size(); ++i) {
        balls.push_back({s[i].point, s[i].radius, BallRef{static_cast<int>(j), static_cast<int>(i)}});
      }
    }
    if (balls.size() < 2) return;
    // The cuts of one round, applied after it (each ball to its smallest cut).
    std::vector<double> cut(balls.size(), std::numeric_limits<double>::infinity());
    bool changed = false;
    for_each_covering_pair(balls, [&](int big, int small) {
      const double d = distance(balls[big].center, balls[small].center);
      const double rb = balls[big].radius, rs = balls[small].radius;
      if (d * d >= 1.001 * (rb * rb - rs * rs)) return;
      // Coincident centres cannot be separated by cutting: equal balls make
      // one vertex, which both features share (see insert_protecting_balls).
      cut[big] = std::min(cut[big], d == 0 ? rs : std::sqrt(0.99 * (d * d + rs * rs)));
      changed = true;
    });
    if (!changed) return;
    for (std::size_t k = 0; k < balls.size(); ++k) {
      if (cut[k] < balls[k].radius) clamp_radius(balls[k].ref, cut[k]);
    }
  }
}

}  // namespace rdmesh::detail
