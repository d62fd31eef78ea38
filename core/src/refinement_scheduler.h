// Private to core/: the order of the rules (RR-7912 section 3): an arc (R1,
// R2) before a facet (R3, R4) before a cell (R5). Each step takes the worst
// element of the first level whose queue is not empty and refines it.
#pragma once

#include <cstddef>

#include "insertion.h"
#include "level_cells.h"
#include "level_curves.h"
#include "level_facets.h"

namespace rdmesh::detail {

class RefinementScheduler {
 public:
  /// All must outlive the scheduler.
  RefinementScheduler(CurveLevel& curves, FacetLevel& facets, CellLevel& cells,
                      Insertion& insertion)
      : curves_(curves), facets_(facets), cells_(cells), insertion_(insertion) {}

  enum class Step {
    kRefined,    ///< an element was refined (a point inserted, or the guard refused it)
    kStale,      ///< the popped entry no longer needed refining
    kConflicts,  ///< only cells are left and the curve level has conflicts (stop_on_conflict)
    kDone,       ///< every queue is empty: no rule applies
  };
  /// One step. With `stop_on_conflict`, stops before the first cell once the
  /// surface rules are done if the curve level found conflicts.
  Step step(bool stop_on_conflict);
  /// The elements still queued, all levels together.
  std::size_t queued() const { return curves_.size() + facets_.size() + cells_.size(); }

 private:
  CurveLevel& curves_;
  FacetLevel& facets_;
  CellLevel& cells_;
  Insertion& insertion_;
};

}  // namespace rdmesh::detail
