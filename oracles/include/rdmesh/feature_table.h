// The tables an oracle answers its feature queries and initial_points() from:
// corners and curves numbered 1..n in the order they are added, each curve's
// exact queries, and the initial points of each patch by its id. The implicit,
// triangle-mesh and CAD oracles keep theirs in one, so all three number their
// features, look them up and refuse an unknown id the same way; a custom
// oracle with sharp features may use it too.
#pragma once

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "rdmesh/curve.h"

namespace rdmesh {

/// The one error for a feature id outside 1..count: OracleError
/// "no curve 7 (ids 1..6)", or "no curve 7 (there are none)" when count is 0.
[[noreturn]] void throw_unknown_id(const char* kind, int id, std::size_t count);

/// `CurveT` is the oracle's own curve class (its code may need more of a curve
/// than the Curve queries); curve() hands it out as that class.
template <class CurveT = Curve>
class FeatureTable {
 public:
  // --- Corners: ids 1..n in the order added ---

  /// Adds a corner at p with the next id and no curves or patches yet.
  CornerInfo& add_corner(const Point3& p) {
    corners_.push_back({CornerId(static_cast<int>(corners_.size()) + 1), p, {}, {}});
    return corners_.back();
  }
  /// Corner `id`; throws the unknown-id OracleError outside 1..n.
  CornerInfo& corner(CornerId id) { return corners_[index(id.value, corners_.size(), "corner")]; }
  const std::vector<CornerInfo>& corners() const { return corners_; }
  /// For passes over every corner (sorting their lists); ids must not change.
  std::vector<CornerInfo>& corners() { return corners_; }

  // --- Curves: ids 1..n in the order added ---

  /// The id the next add_curve() gives.
  CurveId next_curve_id() const { return CurveId(static_cast<int>(curves_.size()) + 1); }
  /// Adds a curve with its queries; sets info.id to next_curve_id().
  CurveInfo& add_curve(CurveInfo info, std::unique_ptr<CurveT> queries) {
    info.id = next_curve_id();
    infos_.push_back(std::move(info));
    curves_.push_back(std::move(queries));
    return infos_.back();
  }
  const std::vector<CurveInfo>& curves() const { return infos_; }
  /// Curve `id`'s queries; throws the unknown-id OracleError outside 1..n.
  const CurveT& curve(CurveId id) const {
    return *curves_[index(id.value, curves_.size(), "curve")];
  }

  // --- Initial points of patches 1..n ---

  /// Patches 1..count, none with points yet.
  void set_patch_count(std::size_t count) { points_.assign(count, {}); }
  /// Appends to patch `id`'s points; throws the unknown-id OracleError outside 1..n.
  void add_initial_points(PatchId id, const std::vector<Point3>& points) {
    std::vector<Point3>& to = points_[index(id.value, points_.size(), "patch")];
    to.insert(to.end(), points.begin(), points.end());
  }
  /// Patch `id`'s points; empty for an id outside 1..n (a patch no point was found on).
  const std::vector<Point3>& initial_points(PatchId id) const {
    static const std::vector<Point3> none;
    const bool known = id.value >= 1 && static_cast<std::size_t>(id.value) <= points_.size();
    return known ? points_[static_cast<std::size_t>(id.value) - 1] : none;
  }
  /// All patches' points together.
  std::size_t initial_point_count() const {
    std::size_t n = 0;
    for (const std::vector<Point3>& p : points_) n += p.size();
    return n;
  }

 private:
  static std::size_t index(int id, std::size_t count, const char* kind) {
    if (id < 1 || static_cast<std::size_t>(id) > count) throw_unknown_id(kind, id, count);
    return static_cast<std::size_t>(id) - 1;
  }

  std::vector<CornerInfo> corners_;
  std::vector<CurveInfo> infos_;
  std::vector<std::unique_ptr<CurveT>> curves_;
  std::vector<std::vector<Point3>> points_;
};

}  // namespace rdmesh
