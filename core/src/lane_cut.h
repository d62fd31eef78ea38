// The cut of a refinement round (refinement_lanes.h): which lane a vertex,
// hence a cell, belongs to, read from the vertices' points. Exudation stores
// this cut's sides in the vertices (assign_lanes_at); refinement does not, so a
// round's new cut costs no pass over every vertex (a tenth of a second of
// the rounds at 1 M tets, most of it on one thread at the end).
#pragma once

#include <iterator>
#include <vector>

#include "triangulation_types.h"

namespace rdmesh::detail {

struct LaneCut {
  int axis = 0;
  double split = 0;
  Vertex_handle infinite;
  /// Whether the infinite vertex holds both lanes (cells across the hull may
  /// be a lane's), set by cut_at; else it holds none.
  bool infinite_in_lanes = false;

  /// Lane 0 holds the finite vertices below `split` along `axis`, lane 1
  /// those at or above.
  bool holds(Vertex_handle v, int lane) const {
    if (v == infinite) return infinite_in_lanes;
    return (v->point().point()[axis] < split) == (lane == 0);
  }
  /// Whether cell c lies in lane `lane` (all its vertices hold it).
  bool in_lane(Cell_handle c, int lane) const {
    return holds(c->vertex(0), lane) && holds(c->vertex(1), lane) && holds(c->vertex(2), lane) &&
           holds(c->vertex(3), lane);
  }
};

/// The cut at `split` on `axis` of `tr`: the infinite vertex holds both lanes
/// when some infinite cell has finite vertices in both (its cell() then
/// becomes that cell, which no lane owns, so no lane rewrites it).
inline LaneCut cut_at(Triangulation& tr, int axis, double split) {
  LaneCut cut{axis, split, tr.infinite_vertex(), false};
  std::vector<Cell_handle> hull;
  tr.incident_cells(cut.infinite, std::back_inserter(hull));
  for (const Cell_handle& c : hull) {
    bool lane[2] = {false, false};
    for (int k = 0; k < 4; ++k)
      if (c->vertex(k) != cut.infinite) lane[cut.holds(c->vertex(k), 1)] = true;
    if (lane[0] && lane[1]) {
      cut.infinite->set_cell(c);
      cut.infinite_in_lanes = true;
      break;
    }
  }
  return cut;
}

}  // namespace rdmesh::detail
