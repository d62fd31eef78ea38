// Private to core/: rule R5 on two threads, with a result that does not depend
// on the threads (issue 19).
//
// A plane cuts space in two lanes (optimize/exudation_lanes.h: every vertex
// carries its lane's bit); a lane owns the cells whose vertices are all its
// own, and the cell level queues each bad cell in the queue of the lane that
// owns it (the others, on the cut, in its own queue for the sequential steps).
// In a round, each lane refines the cells of its queue, worst first, on its own
// thread: it inserts a cell's circumcentre when the conflict zone and every
// cell next to it are its own, finite, and free of curve and corner vertices
// and of protecting balls, when no restricted facet's ball holds the centre and
// the minimum-size guard lets it in; anything else waits for the sequential
// steps (the scheduler: arcs, facets, and the cells nobody owns). Lanes then
// write only cells they own and read only those and their neighbours, which
// the other lane never writes: a facet has three vertices, so a cell next to
// one lane's cell is not the other's. Cells, vertices and stamps come from
// per-lane pools topped up between the steps of a round; the facets a lane
// finds in D|S and the cells it leaves are handed over after the round, lane
// by lane. So each lane does exactly what it would do alone: one thread runs
// the lanes one after the other and gets the same triangulation, to the byte.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "deadline.h"
#include "level_cells.h"
#include "level_curves.h"
#include "level_facets.h"
#include "optimize/cone_hole.h"
#include "rdmesh/mesher.h"
#include "restricted_complex.h"
#include "triangulation_walks.h"

namespace rdmesh::detail {

class RefinementLanes {
 public:
  /// All must outlive the lanes. `min_size`: Insertion's guard. `threads`:
  /// MeshOptions::threads (the lanes run on one thread when the cell size's
  /// field may not be called from several threads: ScalarField::is_concurrent).
  RefinementLanes(RestrictedComplex& complex, CellLevel& cells, FacetLevel& facets,
                  const CurveLevel& curves, const Criteria& criteria, double min_size, int threads);

  /// Cuts space along its longest axis through the middle of the vertices and
  /// turns the cell level's lanes on. Before the first cells are queued.
  void start();
  /// Gives a vertex the sequential steps inserted the bit of its lane.
  void place(Vertex_handle v) const;
  /// Whether a lane has cells queued.
  bool pending() const;
  /// One round: a new cut (alternating the two longest axes) through the
  /// median of the queued cells' centres, the lanes' queues shared out again,
  /// then both lanes refine. Stops early at `deadline` (true then).
  bool round(RefinementStats& stats, const Deadline& deadline);

 private:
  struct Lane;
  /// Refines lane `lane`'s queue until it empties, its pools run low or its
  /// step ends (Lane::full then).
  void run(Lane& lane);
  /// Inserts the circumcentre of the lane's cell `e.cell`, or says why not.
  enum class Outcome { kInserted, kDropped, kDeferred, kCrossed, kFull };
  Outcome refine(Lane& lane, const ElementEntry& e);

  RestrictedComplex& complex_;
  Triangulation& tr_;
  CellLevel& cells_;
  FacetLevel& facets_;
  const CurveLevel& curves_;
  double min_size_sq_;
  int threads_;
  std::array<int, 3> axes_{0, 1, 2};
  int axis_ = 0;
  double split_ = 0;
  std::size_t rounds_ = 0;
  std::vector<ElementEntry> crossed_;  ///< entries whose zone crossed the last cut
};

}  // namespace rdmesh::detail
