// The insertion of a refinement point into its conflict zone, behind the
// minimum-size guard (see core/README.md, "Termination guard").
#include "insertion.h"

#include <algorithm>
#include <iterator>

namespace rdmesh::detail {

Insertion::Insertion(RestrictedComplex& complex, const RestrictedCurves& curves, double min_size,
                     RefinementStats& stats)
    : complex_(complex),
      tr_(complex.triangulation()),
      curves_(curves),
      min_size_sq_(min_size * min_size),
      stats_(stats) {
  zone_cells_.reserve(64);
  zone_boundary_.reserve(128);
}

bool Insertion::find_zone(const Weighted_point& p, Cell_handle start) {
  if (tr_.side_of_power_sphere(start, p) != CGAL::ON_BOUNDED_SIDE) start = tr_.locate(p, start);
  zone_cells_.clear();
  zone_boundary_.clear();
  if (tr_.dimension() == 3)
    conflict_walk_.zone(tr_, p, start, zone_cells_, zone_boundary_);
  else
    tr_.find_conflicts(p, start, std::back_inserter(zone_boundary_),
                       std::back_inserter(zone_cells_));
  if (observer_) observer_->zone_found(zone_cells_);
  return !zone_cells_.empty();
}

Vertex_handle Insertion::insert(const Weighted_point& p, const VertexInfo& info) {
  // Termination guard: the nearest vertex of p is a vertex of a conflict cell.
  const Point3 q = to_point3(p);
  for (const Cell_handle& z : zone_cells_) {
    for (int k = 0; k < 4; ++k) {
      const Vertex_handle v = z->vertex(k);
      if (!tr_.is_infinite(v) && too_close(q, v)) {
        record_guard(info, v->info());
        return Vertex_handle();
      }
    }
  }
  for (const Cell_handle& z : zone_cells_) complex_.kill(z->info());  // entries become stale
  const Triangulation::Facet& f = zone_boundary_.front();
  const Vertex_handle v =
      tr_.insert_in_hole(p, zone_cells_.begin(), zone_cells_.end(), f.first, f.second);
  v->info() = info;
  if (observer_) observer_->inserted(v);
  return v;
}

void Insertion::record_guard(const VertexInfo& candidate, const VertexInfo& nearest) {
  ++stats_.guard_rejections;
  if (stats_.guard_features.size() >= RefinementStats::kMaxListed) return;
  const std::string what = curves_.describe(candidate) + " near " + curves_.describe(nearest);
  auto& list = stats_.guard_features;
  if (std::find(list.begin(), list.end(), what) == list.end()) list.push_back(what);
}

}  // namespace rdmesh::detail
