// Private to core/: the Delaunay refinement of RR-7912 section 3 (rules R1-R5
// with refine-edge, refine-facet-or-edge and refine-tet-facet-or-edge).
//
// State: one regular triangulation with zero weights (= the Delaunay
// triangulation D(P)); for each cell its label (D|O) and for each facet its
// restricted status (D|S_k) with its surface Delaunay ball; for each curve its
// samples and the restricted Delaunay balls of the arcs between them (D|L_j,
// restricted_curves.h). Three priority queues hold the elements that violate a
// rule, worst first: arcs (R1, R2), facets (R3, R4) and cells (R5). A rule is
// only tested on elements created or touched by an insertion (the conflict
// zone); stale queue entries are recognised by their stamp.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <queue>
#include <string>
#include <vector>

#include "optimize/chain_edges.h"
#include "protection.h"
#include "rdmesh/criteria.h"
#include "rdmesh/mesher.h"
#include "rdmesh/oracle.h"
#include "restricted_curves.h"
#include "triangulation_types.h"
#include "worst_first_heap.h"

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
  const Triangulation& triangulation() const { return tr_; }
  /// Mutable access for the optimizers that run after refine() (core/src/optimize/).
  Triangulation& triangulation() { return tr_; }

 private:
  struct QueueEntry {  // 24 bytes
    double priority;
    Cell_handle cell;
    std::uint32_t stamp;
    int facet;  ///< facet index for the facet queue, -1 for cells
    bool operator<(const QueueEntry& o) const {
      // Worst first; ties broken by age so that runs are deterministic.
      return priority < o.priority || (priority == o.priority && stamp > o.stamp);
    }
  };
  struct ArcEntry {
    double priority;
    std::uint64_t order;  ///< insertion order, for deterministic ties
    ArcRef arc;
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

  // --- D|O and D|S bookkeeping (restricted_complex.cpp) ---
  /// Stamps c and computes its orthocenter and label. `from`, when it is a
  /// labeled finite neighbor, lets the oracle label c by a short walk from
  /// its center (DomainOracle::locate_from) instead of locating from scratch.
  void init_cell(Cell_handle c, Cell_handle from = Cell_handle());
  /// Recomputes facet (c, i)'s restricted status on both sides and queues it if bad.
  void update_facet(Cell_handle c, int i);
  /// The crossing init_cell() kept for facet (c, i), when it was found against
  /// the present neighbor n; forgotten either way.
  std::optional<SurfaceHit> take_crossing(Cell_handle c, int i, Cell_handle n);
  /// The dual Voronoi edge of facet (c, i), clipped to the enlarged box.
  bool dual_segment(Cell_handle c, int i, Point3& a, Point3& b) const;
  /// Badness of a restricted facet (> 0 when R3 or R4 applies).
  double facet_badness(Cell_handle c, int i) const;
  /// Badness of a cell of D|O (> 0 when R5 applies).
  double cell_badness(Cell_handle c) const;
  /// Whether vertex v lies on patch `patch` (on it, or on a curve/corner bounding it).
  bool on_patch(const VertexInfo& v, int patch) const;
  /// The power |x - p|^2 - w of x with respect to the facet's first vertex:
  /// the squared radius of the surface Delaunay ball centred at x.
  double facet_power(Cell_handle c, int i, const Point3& x) const;
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
  /// Badness of an arc (> 0 when R1 or R2 applies).
  double arc_badness(int curve, CurveState::Arc a) const;
  /// The arcs having vertex v as an endpoint.
  void arcs_of(Vertex_handle v, std::vector<std::pair<int, CurveState::Arc>>& out);
  /// The live arc an entry refers to, or nullopt when it was split meanwhile.
  std::optional<CurveState::Arc> find_arc(const ArcRef& ref);
  void push_arc(int curve, CurveState::Arc a, double badness);
  /// The largest restricted edge ball of the conflict zone containing x, if any.
  std::optional<std::pair<int, CurveState::Arc>> encroached_arc(const Point3& x);
  /// After inserting v: arcs of the old zone whose ball now contains v lose their edge (R1).
  void recheck_arcs_after(Vertex_handle v);

  // --- refinement procedures (refiner.cpp) ---
  bool refine_edge(int curve, CurveState::Arc a);
  bool refine_facet_or_edge(Cell_handle c, int i);
  bool refine_tet_facet_or_edge(const QueueEntry& entry);
  /// The largest surface Delaunay ball of the conflict zone containing x, if any.
  bool encroached_facet(const Point3& x, Cell_handle& cell, int& facet) const;
  /// Finds the conflict zone of p starting at `start` (a cell in conflict, else
  /// the walk locates p from it), and its corner and curve vertices.
  bool find_conflict_zone(const Weighted_point& p, Cell_handle start);
  /// Inserts p in the hole found by find_conflict_zone; null if the guard refused it.
  Vertex_handle insert_in_zone(const Weighted_point& p, const VertexInfo& info);
  void after_insertion(Vertex_handle v);
  /// Whether the entry's cell was destroyed (read from live_, not from the
  /// cell, whose memory is cold by the time most entries are popped).
  bool stale(const QueueEntry& e) const { return !is_live(e.stamp); }
  /// Gives c the next stamp and marks it live.
  void stamp_new(CellInfo& c);
  /// Marks a destroyed cell's stamp dead.
  void kill(CellInfo& c);
  bool is_live(std::uint32_t stamp) const { return (live_[stamp >> 6] >> (stamp & 63)) & 1; }
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
  Box3 clip_box_;               ///< oracle box with a margin: rays are clipped to it
  double min_size_sq_;          ///< termination guard (squared)
  double facet_shape_bound_;    ///< 4 sin^2(facet angle): min edge^2 / R^2 below it is bad
  double cell_shape_bound_sq_;  ///< beta_3^2

  Triangulation tr_;
  std::uint32_t next_stamp_ = 1;
  std::uint64_t next_arc_order_ = 0;
  std::priority_queue<ArcEntry> arc_queue_;
  std::priority_queue<QueueEntry> facet_queue_;
  WorstFirstHeap<QueueEntry> cell_queue_;
  std::vector<std::uint64_t> live_;  ///< bit s: the cell stamped s still exists

  std::vector<CurveState> curves_;                ///< index = CurveId - 1
  std::vector<CornerInfo> corners_;               ///< index = CornerId - 1
  std::vector<std::vector<int>> curve_patches_;   ///< index = CurveId - 1
  std::vector<std::vector<int>> corner_patches_;  ///< index = CornerId - 1

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
