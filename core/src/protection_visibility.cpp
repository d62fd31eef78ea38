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
// sqrt(|p - q|^2 + w_p), but never below the smaller one, restores the
// inequality; a cut can expose the cut ball to a still larger one, so the pass
// repeats until nothing changes (see cut_hidden_balls for why it ends).
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

bool cut_hidden_balls(const std::vector<Point3>& centers, std::vector<double>& radii) {
  // First with a margin, each round to the smallest cut it asks of a ball; if
  // that has not settled after kGentleRounds (a long chain of balls, each
  // exposed by the cut of the next), cutting exactly to the smaller radius
  // settles for sure: radii then only take values among the initial ones and
  // every round lowers one, so at most n^2 rounds follow.
  constexpr int kGentleRounds = 100;
  if (centers.size() < 2) return false;
  std::vector<VisibleBall> balls(centers.size());
  bool any = false;
  for (int round = 0;; ++round) {
    for (std::size_t k = 0; k < centers.size(); ++k) balls[k] = {centers[k], radii[k]};
    std::vector<double> cut(balls.size(), std::numeric_limits<double>::infinity());
    bool changed = false;
    for_each_covering_pair(balls, [&](int big, int small) {
      const double d = distance(balls[big].center, balls[small].center);
      const double rb = balls[big].radius, rs = balls[small].radius;
      if (d * d >= 1.001 * (rb * rb - rs * rs)) return;
      // Never below the smaller radius: equal balls hide neither (coincident
      // centres make one vertex, which both features share; see
      // ProtectingBallsLevel::insert_initial_points), whereas a cut below it would make the small
      // ball the larger one, and nearly concentric balls would then take
      // turns cutting each other, round after round.
      const double gentle = std::max(rs, std::sqrt(0.99 * (d * d + rs * rs)));
      cut[big] = std::min(cut[big], round < kGentleRounds ? gentle : rs);
      changed = true;
    });
    if (!changed) return any;
    any = true;
    for (std::size_t k = 0; k < balls.size(); ++k) radii[k] = std::min(radii[k], cut[k]);
  }
}

void ProtectionPlanner::keep_all_visible() {
  std::vector<Point3> centers;
  std::vector<double> radii;
  std::vector<BallRef> refs;
  for (std::size_t q = 0; q < corners_.size(); ++q) {
    centers.push_back(corners_[q].point);
    radii.push_back(corner_radius_[q]);
    refs.push_back(BallRef::at_corner(q));
  }
  for (std::size_t j = 0; j < curves_.size(); ++j) {
    const std::vector<BallSample>& s = curves_[j].samples;
    const std::size_t first = curves_[j].c.info.closed ? 0 : 1;
    for (std::size_t i = first; i + 1 < s.size(); ++i) {
      centers.push_back(s[i].point);
      radii.push_back(s[i].radius);
      refs.push_back(BallRef::on_curve(j, i));
    }
  }
  // Each ball once (a corner's copies at its curves' ends and a closed
  // curve's repeated sample follow it in clamp_radius).
  cut_hidden_balls(centers, radii);
  for (std::size_t k = 0; k < refs.size(); ++k) {
    if (radii[k] < radius_of(refs[k])) clamp_radius(refs[k], radii[k]);
  }
}

}  // namespace rdmesh::detail
