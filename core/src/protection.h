// Private to core/: protecting balls on the sharp features (corners Q and
// curves L), the weighted-point protection that RR-7912's conclusion names as
// the way past its angle hypothesis ([CDR07]; CGAL Mesh_3 does the same).
//
// Every corner and a sequence of points along every curve carry a ball. The
// balls are inserted into the regular triangulation as weighted points
// (weight = radius^2) before any patch point. They satisfy:
//   (B1) consecutive balls of a curve overlap (a corner's ball overlaps the
//        first ball of each incident curve), so the balls of a curve cover it:
//        |c_i - c_j| <= r_i + r_j - kOverlap min(r_i, r_j);
//   (B2) two balls that are not consecutive are disjoint, with a margin,
//        |c_i - c_j| >= r_i + r_j + kGap min(r_i, r_j), when they belong to
//        the same curve, or one is a corner of the other's curve. Balls of
//        unrelated features may overlap, but neither may come near the other's
//        feature: the distance from c_i to feature j near c_j is at least
//        (1 + kGap) r_i, and the other way round;
//   (B3) the chord between consecutive centres is at most twice the edge size
//        (rule R2 of the paper: the restricted edge's ball within the size)
//        and stays within facet_distance of the curve.
// Then the restricted Delaunay triangulation of each curve D|L_j is exactly the
// chain of its consecutive ball centres (a point of the curve has negative
// power to one of its own balls and positive power to every ball that does not
// contain it, so no other ball's power cell reaches the curve), whatever the
// angles at which features meet (rule R1 never fires), and every refinement point of rules R3-R5
// lies outside all balls (a point of non-negative power to every vertex), so no later insertion
// encroaches a curve.
//
// Construction. A corner ball has its own radius (at most the edge size and
// 0.4 of the distance to the nearest other corner). Between the corner balls
// at its ends, a curve is sampled by marching along its arc length with steps
// s(a) = min(2 * edge_size, caps), starting and ending on the corner balls'
// spheres, each sample getting radius kRadiusRatio * step. Caps are point
// constraints (a_k, v_k) spreading as v_k + kGrowth |a - a_k|, so sizes vary
// gradually. Where (B2) or (B3) fails, the balls involved shrink (a cap at a
// curve sample, a smaller radius at a corner) and the curves are sampled
// again, until every ball is fine or would fall below the minimum size (then
// the pair is recorded, like the refinement guard). Then, when the oracle can
// tell (DomainOracle::distance_to_other_patches), a ball coming within
// kClearance radii of a patch its feature does not bound shrinks too (R3
// could not be met where that patch crosses the ball; refinement would find
// it late and start again), and the rounds go on until nothing changes.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "deadline.h"
#include "rdmesh/criteria.h"
#include "rdmesh/curve.h"
#include "rdmesh/debug_assert.h"
#include "rdmesh/oracle.h"
#include "size_caps.h"

namespace rdmesh::detail {

/// A ball centre on a curve: parameter, arc length from the curve's start,
/// point and radius.
struct BallSample {
  double t = 0;
  double arc = 0;
  Point3 point;
  double radius = 0;
};

/// The balls of one curve, ordered by parameter. An open curve starts and ends
/// at its corners (whose radius is the corner's); a closed curve repeats its
/// first sample at t_end, so that arcs are consecutive pairs.
struct CurveProtection {
  std::vector<BallSample> samples;
};

/// A ball of the plan: a corner's (by its index in the corner table) or a
/// curve sample's (by the curve's index in the curve table and the sample's
/// index in its samples). Which of the two is explicit, and each index is read
/// through the accessor of its kind, which checks it (RDMESH_DEBUG_ASSERT).
class BallRef {
 public:
  static BallRef at_corner(std::size_t corner) {
    return BallRef(Kind::kCorner, static_cast<int>(corner), 0);
  }
  static BallRef on_curve(std::size_t curve, std::size_t sample) {
    return BallRef(Kind::kCurveSample, static_cast<int>(curve), static_cast<int>(sample));
  }

  bool is_corner() const { return kind_ == Kind::kCorner; }
  int corner() const {
    RDMESH_DEBUG_ASSERT(is_corner(), "the corner of a curve sample's ball");
    return feature_;
  }
  int curve() const {
    RDMESH_DEBUG_ASSERT(!is_corner(), "the curve of a corner's ball");
    return feature_;
  }
  int sample() const {
    RDMESH_DEBUG_ASSERT(!is_corner(), "the sample index of a corner's ball");
    return sample_;
  }
  /// Whether both name the same ball (whatever their factors).
  bool same_ball(const BallRef& o) const {
    return kind_ == o.kind_ && feature_ == o.feature_ && sample_ == o.sample_;
  }

  double factor = 0.5;  ///< shrink(): the ball's new size, as a fraction of its size

 private:
  enum class Kind : std::int8_t { kCorner, kCurveSample };
  BallRef(Kind kind, int feature, int sample) : kind_(kind), feature_(feature), sample_(sample) {}

  Kind kind_;
  int feature_;  ///< corner or curve index
  int sample_;   ///< sample index on the curve (0 for a corner)
};

/// Whether B2 asks balls a and b to be disjoint, rather than only clear of each
/// other's feature: two balls of one curve, or a corner's ball and a ball of a
/// curve the corner ends. `info_of(j)` is the CurveInfo of curve index j.
template <class InfoOf>
bool related_balls(const BallRef& a, const BallRef& b, InfoOf&& info_of) {
  if (!a.is_corner() && !b.is_corner()) return a.curve() == b.curve();
  if (a.is_corner() && b.is_corner()) return false;
  const int corner = (a.is_corner() ? a : b).corner();
  const CurveInfo& curve = info_of((a.is_corner() ? b : a).curve());
  return !curve.closed && (curve.start.value - 1 == corner || curve.end.value - 1 == corner);
}

struct ProtectionPlan {
  std::vector<CurveProtection> curves;  ///< index = CurveId - 1
  std::vector<double> corner_radius;    ///< index = CornerId - 1
  /// Pairs of balls still violating (B2) when they reached the minimum size,
  /// named "curve A near curve B" (distinct, at most RefinementStats::kMaxListed). Both balls of
  /// such a pair are cut so that neither holds the other's centre (hiding it).
  std::vector<std::string> unresolved;
  std::size_t unresolved_pairs = 0;
  /// Curves (indices) with a ball in such a pair: closer to another feature
  /// than the minimum size lets the mesh separate, so the mesh may not follow
  /// them (ascending, each once).
  std::vector<int> unresolved_curves;
  std::size_t balls = 0;
  double min_radius = 0;
};

/// A ball of the plan as the separation pass sees it (protection.cpp).
struct PlanBall;

/// One curve as the planner sees it.
struct ProtectedCurve {
  CurveInfo info;
  const Curve* curve = nullptr;
};

/// Cuts radii (none grows) until no ball hides another in the regular
/// triangulation of the weighted points (centre, radius^2): every centre lies
/// in its own power cell, |c_i - c_j|^2 >= r_j^2 - r_i^2 for every pair.
/// Returns whether it cut anything.
bool cut_hidden_balls(const std::vector<Point3>& centers, std::vector<double>& radii);

class ProtectionPlanner {
 public:
  static constexpr double kRadiusRatio = 0.6;
  static constexpr double kOverlap = 0.2;
  static constexpr double kGap = 0.1;
  static constexpr double kGrowth = 0.5;
  static constexpr double kJitter = 0.03;
  /// A ball keeps the patches its feature does not bound beyond kClearance
  /// times its radius (the refiner blames a ball for an R3 facet whose surface
  /// centre lies within sqrt(1.5) < kClearance radii of its centre).
  static constexpr double kClearance = 1.25;
  /// The distance B2 asks between the centres of two disjoint balls.
  static double disjoint_distance(double ra, double rb) {
    return ra + rb + kGap * std::min(ra, rb);
  }

  /// `oracle`, when given, is asked for the distance from each ball to the
  /// patches its feature does not bound (DomainOracle::distance_to_other_patches).
  ProtectionPlanner(std::vector<ProtectedCurve> curves, std::vector<CornerInfo> corners,
                    const Criteria& criteria, double min_size,
                    const DomainOracle* oracle = nullptr);

  /// Samples every curve and shrinks balls until (B1)-(B3) hold. Throws
  /// TimeLimitReached once the deadline (set_deadline) has passed.
  ProtectionPlan plan();
  /// The run's time limit: plan() and shrink() stop with TimeLimitReached after it.
  void set_deadline(Deadline::Clock::time_point at) { deadline_.set(at); }
  /// How messages name ball b's feature: "corner N" or "curve NAME".
  std::string name(const BallRef& b) const;
  /// Shrinks the given balls of the last plan by their factors (a refinement
  /// found them reaching into a patch their feature does not bound, or two
  /// unrelated ones overlapping where the surface bends) and plans again into `plan`;
  /// false (plan untouched) when none of them can shrink any more.
  bool shrink(const std::vector<BallRef>& balls, ProtectionPlan& plan);
  /// The curves (indices) a ball protects: those ending at its corner, or its
  /// own and, for the ball next to a corner of an open curve, those ending at
  /// that corner (a feature the ball cannot be separated from there reaches
  /// the corner's curves too: occt_bottle's thread ends).
  std::vector<int> curves_touching(const BallRef& ball) const;

 private:
  struct CurveData {
    ProtectedCurve c;
    double length = 0;
    int start = -1, end = -1;  ///< corner indices (open curves)
    SizeCaps caps;
    std::vector<BallSample> samples;
    bool dirty = true;   ///< caps or corner radii changed since the last sampling
    bool clear = false;  ///< samples checked against the other patches since the last sampling
    bool moved = true;   ///< sampled again since the last separate_balls()
  };

  /// The step size at arc length a of curve j.
  double step_at(const CurveData& d, double a) const;
  /// Arc length at which curve j leaves the ball of radius r around its start
  /// (from_end: around its end, measured from the end).
  double exit_arc(const CurveData& d, const Point3& q, double r, bool from_end) const;
  void sample_curve(CurveData& d);
  /// Shrinks ball b to `factor` of its size (with `below_caps`, of the caps at
  /// its place when they are lower); false when it is at the minimum.
  bool shrink_ball(const BallRef& b, double factor, bool below_caps = false);
  /// Caps the radius of ball b in the final samples (no resampling).
  void clamp_radius(const BallRef& b, double radius);
  double radius_of(const BallRef& b) const;
  /// Cuts larger balls until no ball's centre lies outside its own power cell,
  /// so that no protecting ball is hidden in the regular triangulation (only
  /// matters where B1/B2 could not be met; protection_visibility.cpp).
  void keep_all_visible();
  /// Shrinks balls whose arcs violate (B3); true if any changed.
  bool check_arcs();
  /// Distance from x to ball b's feature near b: the corner itself, or the
  /// arc of its curve between the samples next to it.
  double feature_distance(const BallRef& b, const Point3& x) const;
  /// Shrinks balls violating (B2); true if any changed. Only pairs with a ball
  /// that moved since the last call are tested, but all with `record`, which
  /// only records the violating pairs as unresolved.
  bool separate_balls(bool record);
  /// Every ball once, for separate_balls(): the corners, then each curve's
  /// samples between its ends; all count as moved with `record`.
  std::vector<PlanBall> separation_balls(bool record) const;
  /// Whether a and b are consecutive on a curve (B1 wants them to overlap).
  bool consecutive_balls(const BallRef& a, const BallRef& b) const;
  /// The sizes (B2) asks of a pair's two balls, as fractions of theirs (1: unchanged).
  using PairShrink = std::pair<double, double>;
  /// What (B2) asks of balls b and o, or nullopt when they satisfy it.
  std::optional<PairShrink> pair_violation(const PlanBall& b, const PlanBall& o) const;
  /// Records b and o as a pair left violating (B2) at the minimum size.
  void record_unresolved(const PlanBall& b, const PlanBall& o);
  /// Shrinks balls that come within kClearance radii of a patch their feature
  /// does not bound (balls not checked since they last changed); true if any changed.
  bool keep_off_patches();
  void resolve();
  ProtectionPlan result() const;
  std::size_t curve_index(const CurveData& d) const { return &d - curves_.data(); }

  std::vector<CurveData> curves_;
  std::vector<CornerInfo> corners_;
  Criteria criteria_;
  double min_size_;
  const DomainOracle* oracle_;
  std::vector<double> corner_radius_;
  std::vector<char> corner_clear_;  ///< corner checked against the other patches at its radius
  std::vector<char> corner_moved_;  ///< radius changed since the last separate_balls()
  std::vector<std::string> unresolved_;
  std::size_t unresolved_pairs_ = 0;
  std::vector<char> unresolved_curve_;  ///< per curve: a ball in an unresolved pair
  Deadline deadline_;
};

}  // namespace rdmesh::detail
