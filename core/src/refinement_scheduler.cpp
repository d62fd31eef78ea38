// The paper's priority order over the three levels.
#include "refinement_scheduler.h"

namespace rdmesh::detail {

RefinementScheduler::Step RefinementScheduler::step(bool stop_on_conflict) {
  if (!curves_.empty()) {
    return curves_.refine_next(insertion_) ? Step::kRefined : Step::kStale;
  }
  if (!facets_.empty()) {
    const std::optional<ElementEntry> e = facets_.pop();
    if (!e) return Step::kStale;
    facets_.refine(e->cell, e->facet, insertion_, curves_);
    return Step::kRefined;
  }
  if (!cells_.empty()) {
    if (stop_on_conflict && curves_.has_conflicts()) return Step::kConflicts;
    const std::optional<ElementEntry> e = cells_.pop();
    if (!e) return Step::kStale;
    cells_.refine(*e, insertion_, curves_, facets_);
    return Step::kRefined;
  }
  return Step::kDone;
}

}  // namespace rdmesh::detail
