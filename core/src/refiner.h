// Private to core/: the Delaunay refinement of RR-7912 section 3 (rules R1-R5
// with refine-edge, refine-facet-or-edge and refine-tet-facet-or-edge), put
// together from its parts:
//   restricted_complex.h    D(P) with D|O and D|S
//   restricted_curves.h     D|L
//   level_curves.h          R1-R2 on the arcs, or the protecting balls (a strategy)
//   level_facets.h          R3-R4 on the facets of D|S
//   level_cells.h           R5 on the cells of D|O
//   refinement_scheduler.h  the order: arcs, then facets, then cells
//   insertion.h             conflict zone, minimum-size guard, insertion
// The refiner inserts P_0, runs the scheduler and, after each insertion,
// brings the complex and the levels' queues up to date around the new vertex:
// a rule is only tested on elements created or touched by an insertion (the
// conflict zone); stale queue entries are recognised by their stamp.
#pragma once

#include <chrono>
#include <memory>
#include <vector>

#include "deadline.h"
#include "insertion.h"
#include "level_cells.h"
#include "level_curves.h"
#include "level_facets.h"
#include "optimize/chain_edges.h"
#include "protection.h"
#include "rdmesh/criteria.h"
#include "rdmesh/mesher.h"
#include "rdmesh/oracle.h"
#include "refinement_lanes.h"
#include "refinement_scheduler.h"
#include "restricted_complex.h"
#include "restricted_curves.h"
#include "triangulation_types.h"
#include "triangulation_walks.h"

namespace rdmesh::detail {

class Refiner final : private InsertionObserver {
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
  const std::vector<BallRef>& conflicts() const { return curve_level_->conflicts(); }
  /// The tetrahedra of D|O, the triangles of D|S and the edges of D|L, labelled.
  /// `cosines` (only after exudation, which leaves every cell its shape):
  /// also each tetrahedron's max_dihedral_cosine (optimize/tet_shape.h), in
  /// the mesh's order: the cell's shape_cosine, the same bits (the same points
  /// in the same order).
  TetMesh extract_mesh(std::vector<double>* cosines = nullptr);

  const RefinementStats& stats() const { return stats_; }
  /// The edges of D|L: consecutive samples of every curve.
  ChainEdges chain_edges() const { return curves_.chain_edges(); }
  const Triangulation& triangulation() const { return complex_.triangulation(); }
  /// Mutable access for the optimizers that run after refine() (core/src/optimize/).
  Triangulation& triangulation() { return complex_.triangulation(); }

 private:
  /// Records that refinement stopped at the deadline, with what is still queued.
  void stop_at_time_limit();
  struct PatchPoints {
    std::size_t offered = 0;   ///< initial points of the patches
    std::size_t kept_out = 0;  ///< those the curve level kept out
    Cell_handle hint;          ///< near the last point inserted
  };
  /// P_0's points on the patches (DomainOracle::initial_points).
  PatchPoints insert_patch_points();
  /// Surface only, a flat surface: eight far points give D(P) its third dimension.
  void lift_flat_surface(Cell_handle hint);

  // InsertionObserver.
  void zone_found(const std::vector<Cell_handle>& zone) override;
  /// The new cells get their labels, their facets' restricted status and their
  /// places in the facet and cell queues; then the curve level sees v.
  void inserted(Vertex_handle v) override;
  /// Recomputes facet (c, i)'s restricted status (RestrictedComplex) and queues it if bad.
  void update_facet(Cell_handle c, int i);
  void report_progress();
  /// Appends the edges of D|L and the corner vertices (after cells and facets).
  void extract_features(TetMesh& mesh);
  /// Surface only: every restricted facet once, oriented consistently.
  template <class IndexOf>
  void extract_surface(TetMesh& mesh, IndexOf& index_of);

  const DomainOracle& oracle_;
  Criteria criteria_;
  MeshOptions options_;
  RefinementStats stats_;

  RestrictedComplex complex_;
  Triangulation& tr_;  ///< complex_'s
  RestrictedCurves curves_;
  Insertion insertion_;
  std::unique_ptr<CurveLevel> curve_level_;  ///< R1-R2, or the protecting balls
  FacetLevel facets_;                        ///< R3-R4
  CellLevel cells_;                          ///< R5
  RefinementScheduler scheduler_;
  RefinementLanes lanes_;  ///< R5 in two lanes, between the scheduler's sequential steps

  std::vector<Cell_handle> new_cells_;  ///< scratch: the star of the vertex just inserted
  StarWalk walk_;
  std::chrono::steady_clock::time_point start_time_;
  Deadline deadline_;  ///< read every 256th insertion or refinement step
  std::size_t insertions_since_progress_ = 0;
};

}  // namespace rdmesh::detail
