// Private to core/: the curve level of RR-7912 section 3, D|L, as a strategy
// with two implementations:
//   CurveRefinementLevel  the paper's rules on the arcs between consecutive
//                         samples of a curve (level_curves.cpp):
//     R1  a vertex not on the arc lies inside the arc's restricted Delaunay
//         ball: the edge is not in D|L_j;
//     R2  the ball is larger than the edge size, or the chord is farther than
//         facet_distance from its centre;
//     refine-edge inserts the ball's centre, on the curve; a facet or cell
//     centre inside an arc's ball refines that arc instead.
//   ProtectingBallsLevel  the protecting balls of [CDR07]
//     (level_protecting_balls.cpp): the curves are sampled once, before any
//     patch point, by weighted points whose chains are D|L already. It never
//     refines; it keeps facet and cell centres out of the balls and reports
//     the balls that reach a patch their feature does not bound (conflicts()).
// The facet and cell levels ask the curve level before inserting a point.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "deadline.h"
#include "insertion.h"
#include "protection.h"
#include "rdmesh/criteria.h"
#include "rdmesh/oracle.h"
#include "restricted_complex.h"
#include "restricted_curves.h"
#include "violation.h"

namespace rdmesh::detail {

class FacetLevel;

class CurveLevel {
 public:
  virtual ~CurveLevel() = default;

  /// P_0 on the features: the corners and the first samples of every curve.
  virtual void insert_initial_points(Deadline& deadline, RefinementStats& stats) = 0;
  /// Whether a patch's initial point p must stay out (hint: a cell near p).
  virtual bool keeps_out(const Point3& p, Cell_handle hint) const = 0;
  /// What keeps the patch points out, for the error when too many are ("... hold").
  virtual std::string keep_out_reason() const = 0;
  /// After P_0 is in the complex: queues the arcs that violate R1 or R2.
  virtual void queue_initial_arcs() {}

  /// Whether any arc waits to be refined, and how many.
  virtual bool empty() const { return true; }
  virtual std::size_t size() const { return 0; }
  /// Pops the worst arc and refines it; false when the entry was stale (the
  /// arc was split since, or no longer violates a rule): no work was done.
  virtual bool refine_next(Insertion& insertion) {
    (void)insertion;
    return false;
  }
  /// A refinement point x of a facet or cell, its conflict zone found: when x
  /// lies in the ball of an arc, that arc is refined instead (refine-edge) and
  /// the answer is whether a point was inserted; nullopt otherwise.
  virtual std::optional<bool> refine_encroached(const Point3& x, Insertion& insertion) {
    (void)x, (void)insertion;
    return std::nullopt;
  }
  /// Whether the centre of facet (c, i) must not be inserted (protecting
  /// balls: inside them, or a ball in conflict). Before its conflict zone.
  virtual bool keeps_facet_centre(Cell_handle c, int i, const VertexInfo& info,
                                  Insertion& insertion) {
    (void)c, (void)i, (void)info, (void)insertion;
    return false;
  }
  /// Whether the centre of cell c must not be inserted (inside the balls).
  virtual bool keeps_cell_centre(Cell_handle c) const {
    (void)c;
    return false;
  }
  /// Before refinement: the conflicts the facets between the features show
  /// already (protecting balls); true when there are some.
  virtual bool find_early_conflicts(const FacetLevel& facets) {
    (void)facets;
    return false;
  }
  /// Whether refinement found a ball reaching a patch its feature does not bound.
  virtual bool has_conflicts() const { return false; }
  /// Those balls (protecting balls only).
  virtual const std::vector<BallRef>& conflicts() const;

  // InsertionObserver's two events, for the curves.
  virtual void zone_found(const std::vector<Cell_handle>& zone) { (void)zone; }
  virtual void inserted(Vertex_handle v) { (void)v; }
};

/// RR-7912's R1 and R2 on the arcs (level_curves.cpp).
class CurveRefinementLevel final : public CurveLevel {
 public:
  /// All must outlive the level.
  CurveRefinementLevel(RestrictedCurves& curves, RestrictedComplex& complex,
                       const Criteria& criteria);

  void insert_initial_points(Deadline& deadline, RefinementStats& stats) override;
  bool keeps_out(const Point3& p, Cell_handle hint) const override;
  std::string keep_out_reason() const override { return "curve samples keep out "; }
  void queue_initial_arcs() override;
  bool empty() const override { return queue_.empty(); }
  std::size_t size() const override { return queue_.size(); }
  bool refine_next(Insertion& insertion) override;
  std::optional<bool> refine_encroached(const Point3& x, Insertion& insertion) override;
  void zone_found(const std::vector<Cell_handle>& zone) override;
  void inserted(Vertex_handle v) override;

  /// The worst part of R2 the arc violates (R1 needs the triangulation: see
  /// update_arc).
  Violation violation(int curve, CurveState::Arc a) const;
  /// Computes the restricted Delaunay ball of the arc starting at `a`, and
  /// queues it when it violates R1 (its ball holds another vertex than its
  /// ends) or R2. Returns the violation found.
  Violation update_arc(int curve, CurveState::Arc a);
  /// refine-edge: inserts the centre of the arc's ball, on the curve.
  bool refine_edge(int curve, CurveState::Arc a, Insertion& insertion);

 private:
  struct ArcEntry {
    double priority;
    std::uint64_t order;  ///< insertion order, for deterministic ties
    ArcRef arc;
    Rule rule;  ///< R1 entries stay valid while the arc exists
    bool operator<(const ArcEntry& o) const {
      return priority < o.priority || (priority == o.priority && order > o.order);
    }
  };
  void push(int curve, CurveState::Arc a, const Violation& violation);
  /// The largest restricted edge ball of the conflict zone containing x, if any.
  std::optional<std::pair<int, CurveState::Arc>> encroached_arc(const Point3& x);

  RestrictedCurves& curves_;
  Triangulation& tr_;
  const Criteria& criteria_;
  std::uint64_t next_order_ = 0;
  std::priority_queue<ArcEntry> queue_;
  std::vector<Vertex_handle> zone_feature_vertices_;  ///< corner/curve vertices of the zone
  std::vector<std::pair<int, CurveState::Arc>> arcs_scratch_;
};

/// The protecting balls of a ProtectionPlan (level_protecting_balls.cpp).
class ProtectingBallsLevel final : public CurveLevel {
 public:
  /// All must outlive the level.
  ProtectingBallsLevel(const ProtectionPlan& plan, RestrictedCurves& curves,
                       RestrictedComplex& complex, const DomainOracle& oracle,
                       const Criteria& criteria);

  void insert_initial_points(Deadline& deadline, RefinementStats& stats) override;
  /// Nothing is ever inserted inside a protecting ball.
  bool keeps_out(const Point3& p, Cell_handle hint) const override;
  std::string keep_out_reason() const override { return "protecting balls of the curves hold "; }
  bool keeps_facet_centre(Cell_handle c, int i, const VertexInfo& info,
                          Insertion& insertion) override;
  /// An orthosphere of non-positive radius lies inside the protecting balls.
  bool keeps_cell_centre(Cell_handle c) const override { return !(c->info().squared_radius > 0); }
  bool find_early_conflicts(const FacetLevel& facets) override;
  bool has_conflicts() const override { return !conflicts_.empty(); }
  const std::vector<BallRef>& conflicts() const override { return conflicts_; }

  /// A weighted vertex of the R3-violating facet (c, i) whose feature does
  /// not bound the facet's patch and whose ball reaches its surface centre;
  /// records it in conflicts().
  bool ball_conflict(Cell_handle c, int i);
  /// A facet of D|S joining the balls of unrelated features (B2 lets those
  /// overlap, and refinement never puts a point inside them) whose centroid
  /// strays beyond the facet distance from the surface along its normal:
  /// records those balls in conflicts(), so that they shrink.
  void overlap_conflict(Cell_handle c, int i);

 private:
  /// The plan's ball of a weighted vertex.
  BallRef ball_of(const VertexInfo& v) const;
  /// Records b in conflicts_ once.
  void add_conflict(const BallRef& b);

  const ProtectionPlan& plan_;
  RestrictedCurves& curves_;
  RestrictedComplex& complex_;
  Triangulation& tr_;
  const DomainOracle& oracle_;
  const Criteria& criteria_;
  std::vector<BallRef> conflicts_;
};

}  // namespace rdmesh::detail
