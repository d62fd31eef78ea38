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
    conflict_walk(p, start);
  else
    tr_.find_conflicts(p, start, std::back_inserter(zone_boundary_),
                       std::back_inserter(zone_cells_));
  if (observer_) observer_->zone_found(zone_cells_);
  return !zone_cells_.empty();
}

void Insertion::conflict_walk(const Weighted_point& p, Cell_handle start) {
  // Regular_triangulation_3::find_conflicts' depth-first walk, step for step
  // (the same cells and facets in the same order, the same exact test), but
  // with a stack kept between calls (CGAL allocates two vectors per call) and
  // each cell's neighbours prefetched before they are tested: the walk is
  // bound by memory latency, and the prefetches make its misses overlap.
  auto in_conflict = [&](Cell_handle c) {
    return tr_.side_of_power_sphere(c, p, /*perturb=*/true) == CGAL::ON_BOUNDED_SIDE;
  };
  if (!in_conflict(start)) return;
  stack_.clear();
  stack_.push_back(start);
  start->tds_data().mark_in_conflict();
  zone_cells_.push_back(start);
  do {
    const Cell_handle c = stack_.back();
    stack_.pop_back();
    for (int i = 0; i < 4; ++i) __builtin_prefetch(&*c->neighbor(i));
    for (int i = 0; i < 4; ++i) {
      const Cell_handle n = c->neighbor(i);
      if (n->tds_data().is_clear())
        for (int k = 0; k < 4; ++k) __builtin_prefetch(&*n->vertex(k));
    }
    for (int i = 0; i < 4; ++i) {
      const Cell_handle test = c->neighbor(i);
      if (test->tds_data().is_in_conflict()) continue;
      if (test->tds_data().is_clear()) {
        if (in_conflict(test)) {
          stack_.push_back(test);
          test->tds_data().mark_in_conflict();
          zone_cells_.push_back(test);
          continue;
        }
        test->tds_data().mark_on_boundary();
      }
      zone_boundary_.emplace_back(c, i);
    }
  } while (!stack_.empty());
  for (const Triangulation::Facet& f : zone_boundary_)
    f.first->neighbor(f.second)->tds_data().clear();
  for (const Cell_handle& c : zone_cells_) c->tds_data().clear();
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
