// Private to core/: a queued element of the restricted complex, a facet
// (cell, facet index) or a cell, with the priority of its violation.
#pragma once

#include <cstdint>

#include "triangulation_types.h"

namespace rdmesh::detail {

struct ElementEntry {  // 24 bytes
  double priority;
  Cell_handle cell;
  std::uint32_t stamp;  ///< the cell's stamp when queued: a dead stamp means a stale entry
  int facet;            ///< facet index for the facet queue, -1 for cells
  bool operator<(const ElementEntry& o) const {
    // Worst first; ties broken by age so that runs are deterministic.
    return priority < o.priority || (priority == o.priority && stamp > o.stamp);
  }
};

}  // namespace rdmesh::detail
