// Private to core/: the two walks through the triangulation that the
// refinement and the exudation repeat millions of times, each listing exactly
// what CGAL's own walk lists, in the same order (so that no result changes),
// but cheaper:
//  - StarWalk, the cells incident to a vertex, as
//    Triangulation_3::incident_cells lists them;
//  - ConflictWalk, the conflict zone of a weighted point and its boundary
//    facets, as Regular_triangulation_3::find_conflicts lists them.
// CGAL builds a stack (and find_conflicts two vectors) on each call; these
// keep theirs between calls. And both walks are bound by memory latency, the
// cells of a star lying far apart in a mesh of millions: before looking at a
// cell's neighbours they ask for all of them at once (a prefetch), so that
// their cache misses overlap instead of following one another.
#pragma once

#include <vector>

#include "triangulation_types.h"

namespace rdmesh::detail {

/// The star of a vertex (a depth-first walk from v->cell(), each cell once,
/// in the order it is first reached).
class StarWalk {
 public:
  /// Replaces `out` by the cells incident to v (tr three-dimensional).
  void cells(Vertex_handle v, std::vector<Cell_handle>& out) {
    cells_if(v, out, [](Cell_handle) { return true; });
  }

  /// As cells(), but marks a cell only once accept(cell) said yes: false,
  /// with `out` incomplete, as soon as it says no. An exudation lane walks this
  /// way, so that it never writes a cell it does not own (it reads the marks of
  /// cells around its own vertices, which no other lane owns or marks).
  template <class Accept>
  bool cells_if(Vertex_handle v, std::vector<Cell_handle>& out, Accept accept) {
    out.clear();
    const Cell_handle d = v->cell();
    if (!accept(d)) return false;
    stack_.clear();
    stack_.push_back(d);
    d->tds_data().mark_in_conflict();
    out.push_back(d);
    bool accepted = true;
    do {
      const Cell_handle c = stack_.back();
      stack_.pop_back();
      for (int i = 0; i < 4; ++i)
        if (c->vertex(i) != v) __builtin_prefetch(&*c->neighbor(i));
      for (int i = 0; i < 4; ++i) {
        if (c->vertex(i) == v) continue;
        const Cell_handle next = c->neighbor(i);
        if (!next->tds_data().is_clear()) continue;
        if (!accept(next)) {
          accepted = false;
          break;
        }
        stack_.push_back(next);
        next->tds_data().mark_in_conflict();
        out.push_back(next);
      }
    } while (accepted && !stack_.empty());
    for (const Cell_handle& c : out) c->tds_data().clear();
    return accepted;
  }

 private:
  std::vector<Cell_handle> stack_;
};

/// The conflict zone of a weighted point in a three-dimensional regular
/// triangulation: the cells whose orthosphere it is in conflict with (CGAL's
/// exact, perturbed power test), found depth-first from a start cell in
/// conflict, and the facets bounding them.
class ConflictWalk {
 public:
  /// Replaces `cells` and `boundary` by the zone of p found from `start`
  /// (both empty when `start` is not in conflict with p). The boundary facets
  /// are seen from inside: (cell of the zone, index of the facet).
  void zone(const Triangulation& tr, const Weighted_point& p, Cell_handle start,
            std::vector<Cell_handle>& cells, std::vector<Triangulation::Facet>& boundary) {
    zone_if(tr, p, start, cells, boundary, [](Cell_handle) { return true; });
  }

  /// As zone(), but reads a cell's vertices, and marks it, only once
  /// accept(cell) said yes, for every cell of the zone and every cell next to
  /// it: false, with `cells` and `boundary` incomplete, as soon as it says no.
  /// A refinement lane walks this way (refinement_lanes.h): it never reads
  /// nor writes past the cells it owns and their neighbours.
  template <class Accept>
  bool zone_if(const Triangulation& tr, const Weighted_point& p, Cell_handle start,
               std::vector<Cell_handle>& cells, std::vector<Triangulation::Facet>& boundary,
               Accept accept) {
    cells.clear();
    boundary.clear();
    auto in_conflict = [&](Cell_handle c) {
      return tr.side_of_power_sphere(c, p, /*perturb=*/true) == CGAL::ON_BOUNDED_SIDE;
    };
    if (!accept(start)) return false;
    if (!in_conflict(start)) return true;
    stack_.clear();
    stack_.push_back(start);
    start->tds_data().mark_in_conflict();
    cells.push_back(start);
    bool accepted = true;
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
          if (!accept(test)) {
            accepted = false;
            break;
          }
          if (in_conflict(test)) {
            stack_.push_back(test);
            test->tds_data().mark_in_conflict();
            cells.push_back(test);
            continue;
          }
          test->tds_data().mark_on_boundary();
        }
        boundary.emplace_back(c, i);
      }
    } while (accepted && !stack_.empty());
    for (const Triangulation::Facet& f : boundary) f.first->neighbor(f.second)->tds_data().clear();
    for (const Cell_handle& c : cells) c->tds_data().clear();
    return accepted;
  }

 private:
  std::vector<Cell_handle> stack_;
};

}  // namespace rdmesh::detail
