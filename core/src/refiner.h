// Private to core/: the Delaunay refinement of RR-7912 section 3 for domains
// bounded by smooth patches (rules R3, R4, R5 and refine-tet-facet-or-edge).
//
// State: one regular triangulation with zero weights (= the Delaunay
// triangulation D(P)); for each cell its label (D|O) and for each facet its
// restricted status (D|S_k) with its surface Delaunay ball. Two priority
// queues hold the elements that violate a rule, worst first: facets (R3, R4)
// and cells (R5). A rule is only tested on elements created by an insertion
// (the conflict zone); stale queue entries are recognised by their stamp.
#pragma once

#include <chrono>
#include <cstdint>
#include <queue>
#include <vector>

#include "rdmesh/criteria.h"
#include "rdmesh/mesher.h"
#include "rdmesh/oracle.h"
#include "triangulation_types.h"

namespace rdmesh::detail {

class Refiner {
 public:
  Refiner(const DomainOracle& oracle, const Criteria& criteria, const MeshOptions& options);

  /// P_0: at least three points on every connected patch (oracle initial points).
  void insert_initial_points();
  /// Applies R3-R5 until no rule applies (or only guarded elements remain).
  void refine();
  /// The tetrahedra of D|O and the triangles of D|S, labelled.
  TetMesh extract_mesh();

  const RefinementStats& stats() const { return stats_; }
  const Triangulation& triangulation() const { return tr_; }
  /// Mutable access for the optimizers that run after refine() (core/src/optimize/).
  Triangulation& triangulation() { return tr_; }

 private:
  struct QueueEntry {
    double priority;
    std::uint32_t stamp;
    Cell_handle cell;
    int facet;  ///< facet index for the facet queue, -1 for cells
    bool operator<(const QueueEntry& o) const {
      // Worst first; ties broken by age so that runs are deterministic.
      return priority < o.priority || (priority == o.priority && stamp > o.stamp);
    }
  };

  // --- restricted complex bookkeeping (restricted_complex.cpp) ---
  void init_cell(Cell_handle c);
  /// Recomputes facet (c, i)'s restricted status on both sides and queues it if bad.
  void update_facet(Cell_handle c, int i);
  /// The dual Voronoi edge of facet (c, i), clipped to the enlarged box.
  bool dual_segment(Cell_handle c, int i, Point3& a, Point3& b) const;
  /// Badness of a restricted facet (> 0 when R3 or R4 applies).
  double facet_badness(Cell_handle c, int i) const;
  /// Badness of a cell of D|O (> 0 when R5 applies).
  double cell_badness(Cell_handle c) const;

  // --- refinement procedures (refiner.cpp) ---
  void refine_facet(Cell_handle c, int i);
  void refine_tet(const QueueEntry& entry);
  /// Finds the conflict zone of p starting at `start` (a cell in conflict).
  bool find_conflict_zone(const Weighted_point& p, Cell_handle start);
  /// Inserts p in the hole found by find_conflict_zone; false if the guard refused it.
  bool insert_in_zone(const Weighted_point& p, FeatureDim dim, int feature);
  void after_insertion(Vertex_handle v);
  bool stale(const QueueEntry& e) const { return e.cell->info().stamp != e.stamp; }
  void report_progress();

  const DomainOracle& oracle_;
  Criteria criteria_;
  MeshOptions options_;
  Box3 clip_box_;              ///< oracle box with a margin: rays are clipped to it
  double min_size_sq_;         ///< termination guard (squared)
  double facet_shape_bound_;   ///< 4 sin^2(facet angle): min edge^2 / R^2 below it is bad
  double cell_shape_bound_sq_; ///< beta_3^2

  Triangulation tr_;
  std::uint32_t next_stamp_ = 1;
  std::priority_queue<QueueEntry> facet_queue_;
  std::priority_queue<QueueEntry> cell_queue_;

  // Scratch buffers reused by every insertion (no allocation in the loop).
  std::vector<Cell_handle> zone_cells_;
  std::vector<Triangulation::Facet> zone_boundary_;
  std::vector<Cell_handle> new_cells_;

  RefinementStats stats_;
  std::chrono::steady_clock::time_point start_time_;
  std::size_t insertions_since_progress_ = 0;
};

}  // namespace rdmesh::detail
