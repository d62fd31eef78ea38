// Private to core/: the Delaunay refinement of RR-7912 section 3 (rules R1-R5
// with refine-edge, refine-facet-or-edge and refine-tet-facet-or-edge).
//
// State: the restricted complex (restricted_complex.h: the regular
// triangulation D(P), the labels of D|O and the restricted facets of D|S_k
// with their surface Delaunay balls); for each curve its samples and the
// restricted Delaunay balls of the arcs between them (D|L_j,
// restricted_curves.h). Each level holds the queue of its elements that
// violate a rule, worst first: arcs (R1, R2), facets (R3, R4,
// level_facets.h) and cells (R5, level_cells.h). A rule is only tested on
// elements created or touched by an insertion (the conflict zone); stale queue
// entries are recognised by their stamp.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <queue>
#include <string>
#include <vector>

#include "level_cells.h"
#include "level_facets.h"
#include "optimize/chain_edges.h"
#include "protection.h"
#include "rdmesh/criteria.h"
#include "rdmesh/mesher.h"
#include "rdmesh/oracle.h"
#include "restricted_complex.h"
#include "restricted_curves.h"
#include "triangulation_types.h"

namespace rdmesh::detail {

class Refiner {
 public:
  /// `plan`: the protecting balls (FeatureMethod::kProtectingBalls), or null
  /// for RR-7912's rules R1/R2 on the curves. The plan must outlive the refiner.
  Refiner(const DomainOracle& oracle, const Criteria& criteria, const MeshOptions& options,
          const ProtectionPlan* plan);

  /// P_0: the corners Q, then samples on every curve (the protecting balls, or
  /// at least two points per curve, corners included), then at least three
  /// points on every connected patch (outside the balls).
  void insert_initial_points();
  /// Applies R1-R5 until no rule applies (or only guarded elements remain).
  /// With `stop_on_conflict`, returns as soon as the surface rules are done
  /// (the facet queue is empty) if a protecting ball was found reaching into
  /// a patch its feature does not bound (see conflicts()).
  void refine(bool stop_on_conflict = false);
  /// Refinement stops when the clock passes `deadline` (stats().time_limit_reached).
  /// insert_initial_points() stops there with TimeLimitReached, refine() with
  /// RefinementStats::time_limit_reached.
  void set_deadline(Deadline::Clock::time_point at) { deadline_.set(at); }
  /// Balls that reached into a patch their feature does not bound (R3 could
  /// not be met there): shrinking them and refining again removes the conflict.
  const std::vector<BallRef>& conflicts() const { return conflicts_; }
  /// The tetrahedra of D|O, the triangles of D|S and the edges of D|L, labelled.
  TetMesh extract_mesh();

  const RefinementStats& stats() const { return stats_; }
  /// The edges of D|L: consecutive samples of every curve.
  ChainEdges chain_edges() const;
  const Triangulation& triangulation() const { return complex_.triangulation(); }
  /// Mutable access for the optimizers that run after refine() (core/src/optimize/).
  Triangulation& triangulation() { return complex_.triangulation(); }

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
  /// An element whose refinement point encroaches a restricted edge or facet.
  struct Encroached {
    int curve = -1;  ///< >= 0: the arc (curve, t) is encroached
    double t = 0;
    Cell_handle cell;  ///< else, when valid: the facet (cell, facet)
    int facet = -1;
  };

  /// Recomputes facet (c, i)'s restricted status (RestrictedComplex) and queues it if bad.
  void update_facet(Cell_handle c, int i);

  // --- protecting balls' conflicts (refiner.cpp) ---
  /// Protecting balls: a weighted vertex of the R3-violating facet (c, i) whose
  /// feature does not bound the facet's patch and whose ball reaches its
  /// surface centre; records it in conflicts_.
  bool ball_conflict(Cell_handle c, int i);
  /// A facet of D|S joining the balls of unrelated features (B2 lets those
  /// overlap, and refinement never puts a point inside them) whose centroid
  /// strays beyond the facet distance from the surface along its normal:
  /// records those balls in conflicts_, so that they shrink. refine(true)
  /// checks the facets between the balls this way before refining.
  void overlap_conflict(Cell_handle c, int i);
  /// The plan's ball of a weighted vertex.
  BallRef ball_of(const VertexInfo& v) const;
  /// Records b in conflicts_ once.
  void add_conflict(const BallRef& b);

  // --- D|L bookkeeping (restricted_curves.cpp) ---
  void load_curves();
  void insert_corners_and_curve_samples();
  /// Protecting balls: the plan's corners and curve samples as weighted points.
  void insert_protecting_balls();
  /// A point that may be inserted: outside every protecting ball.
  bool outside_balls(const Point3& p, Cell_handle hint) const;
  /// Computes the restricted Delaunay ball of the arc starting at `a` and queues it if bad.
  void create_arc(int curve, CurveState::Arc a, bool check_empty);
  /// The worst part of R2 the arc violates (R1 needs the triangulation: create_arc).
  Violation arc_violation(int curve, CurveState::Arc a) const;
  /// The arcs having vertex v as an endpoint.
  void arcs_of(Vertex_handle v, std::vector<std::pair<int, CurveState::Arc>>& out);
  /// The live arc an entry refers to, or nullopt when it was split meanwhile.
  std::optional<CurveState::Arc> find_arc(const ArcRef& ref);
  void push_arc(int curve, CurveState::Arc a, const Violation& violation);
  /// The largest restricted edge ball of the conflict zone containing x, if any.
  std::optional<std::pair<int, CurveState::Arc>> encroached_arc(const Point3& x);
  /// After inserting v: arcs of the old zone whose ball now contains v lose their edge (R1).
  void recheck_arcs_after(Vertex_handle v);

  // --- refinement procedures (refiner.cpp) ---
  bool refine_edge(int curve, CurveState::Arc a);
  bool refine_facet_or_edge(Cell_handle c, int i);
  bool refine_tet_facet_or_edge(const ElementEntry& entry);
  /// The largest surface Delaunay ball of the conflict zone containing x, if any.
  bool encroached_facet(const Point3& x, Cell_handle& cell, int& facet) const;
  /// Finds the conflict zone of p starting at `start` (a cell in conflict, else
  /// the walk locates p from it), and its corner and curve vertices.
  bool find_conflict_zone(const Weighted_point& p, Cell_handle start);
  /// Inserts p in the hole found by find_conflict_zone; null if the guard refused it.
  Vertex_handle insert_in_zone(const Weighted_point& p, const VertexInfo& info);
  void after_insertion(Vertex_handle v);
  void report_progress();
  /// Appends the edges of D|L and the corner vertices (after cells and facets).
  void extract_features(TetMesh& mesh);
  /// Surface only: every restricted facet once, oriented consistently.
  template <class IndexOf>
  void extract_surface(TetMesh& mesh, IndexOf& index_of);
  /// Counts a point refused by the minimum-size guard and names the features involved.
  void record_guard(const VertexInfo& candidate, const VertexInfo& nearest);
  std::string describe(const VertexInfo& v) const;

  const DomainOracle& oracle_;
  Criteria criteria_;
  MeshOptions options_;
  const ProtectionPlan* plan_;  ///< null: RR-7912's R1/R2 on the curves
  std::vector<BallRef> conflicts_;
  double min_size_sq_;  ///< termination guard (squared)

  RestrictedComplex complex_;
  Triangulation& tr_;  ///< complex_'s
  FacetLevel facets_;  ///< R3, R4
  CellLevel cells_;    ///< R5
  std::uint64_t next_arc_order_ = 0;
  std::priority_queue<ArcEntry> arc_queue_;

  std::vector<CurveState> curves_;   ///< index = CurveId - 1
  std::vector<CornerInfo> corners_;  ///< index = CornerId - 1

  // Scratch buffers reused by every insertion (no allocation in the loop).
  std::vector<Cell_handle> zone_cells_;
  std::vector<Triangulation::Facet> zone_boundary_;
  std::vector<Cell_handle> new_cells_;
  std::vector<Vertex_handle> zone_feature_vertices_;  ///< corner/curve vertices of the zone
  std::vector<std::pair<int, CurveState::Arc>> arcs_scratch_;

  RefinementStats stats_;
  std::chrono::steady_clock::time_point start_time_;
  Deadline deadline_;  ///< read every 256th insertion or refinement step
  std::size_t insertions_since_progress_ = 0;
};

}  // namespace rdmesh::detail
