// Private to core/: one insertion of a refinement point, as every level does
// it: the conflict zone of the point (found first, so that the level can look
// for encroached balls in it), the minimum-size termination guard, then
// insert_in_hole. An observer (the refiner) brings the restricted complex and
// the levels' queues up to date around the new vertex.
#pragma once

#include <vector>

#include "rdmesh/mesher.h"
#include "restricted_complex.h"
#include "restricted_curves.h"
#include "triangulation_types.h"
#include "triangulation_walks.h"

namespace rdmesh::detail {

/// What is told about each conflict zone found and each vertex inserted.
class InsertionObserver {
 public:
  virtual ~InsertionObserver() = default;
  /// A conflict zone was found (its cells are still there).
  virtual void zone_found(const std::vector<Cell_handle>& zone) = 0;
  /// v was inserted: its star replaces the zone.
  virtual void inserted(Vertex_handle v) = 0;
};

class Insertion {
 public:
  /// All must outlive the insertion. `min_size`: no point closer than it to
  /// a vertex is inserted (RefinementStats::guard_rejections counts them).
  Insertion(RestrictedComplex& complex, const RestrictedCurves& curves, double min_size,
            RefinementStats& stats);
  void set_observer(InsertionObserver* observer) { observer_ = observer; }

  /// Finds the conflict zone of p starting at `start` (a cell in conflict,
  /// else the walk locates p from it); false when it is empty.
  bool find_zone(const Weighted_point& p, Cell_handle start);
  /// The cells of the zone find_zone() found.
  const std::vector<Cell_handle>& zone() const { return zone_cells_; }
  /// Inserts p in that zone; null when a vertex of the zone is closer than
  /// the minimum size (the guard, recorded).
  Vertex_handle insert(const Weighted_point& p, const VertexInfo& info);
  /// Whether q is closer than the minimum size to vertex v.
  bool too_close(const Point3& q, Vertex_handle v) const {
    return squared_norm(to_point3(v->point()) - q) < min_size_sq_;
  }
  /// Counts a point refused by the guard and names the features involved.
  void record_guard(const VertexInfo& candidate, const VertexInfo& nearest);

  RefinementStats& stats() { return stats_; }

 private:
  RestrictedComplex& complex_;
  Triangulation& tr_;
  const RestrictedCurves& curves_;
  double min_size_sq_;
  RefinementStats& stats_;
  InsertionObserver* observer_ = nullptr;
  // Scratch buffers reused by every insertion (no allocation in the loop).
  std::vector<Cell_handle> zone_cells_;
  std::vector<Triangulation::Facet> zone_boundary_;
  ConflictWalk conflict_walk_;
};

}  // namespace rdmesh::detail
