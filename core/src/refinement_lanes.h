// Private to core/: rules R3, R4 and R5 on two threads, with a result that
// does not depend on the threads (issue 19).
//
// A plane cuts space in two lanes (optimize/exudation_lanes.h: every vertex
// carries its lane's bit); a lane owns the cells whose vertices are all its
// own. The cell level queues each bad cell in the queue of the lane that owns
// it, the facet level each bad facet of D|S whose two cells a lane owns and
// whose surface ball is small (the others, on the cut or in the coarse start,
// in the levels' own queues for the sequential steps, which park the small
// ones for the next round's cut: CellLevel::pop, FacetLevel::pop). In a round, each lane
// refines its facets, then its cells, worst first, on its own thread: it
// inserts the surface ball's centre or the circumcentre when the conflict zone
// and every cell next to it are its own, finite, and free of curve and corner
// vertices and of protecting balls (so no arc's ball holds the point), when,
// for a cell, no restricted facet's ball holds the centre, and when the
// minimum-size guard lets it in; anything else waits for the sequential steps
// (the scheduler: arcs, and the facets and cells nobody owns). Lanes then
// write only cells they own and read only those and their neighbours, which
// the other lane never writes: a facet has three vertices, so a cell next to
// one lane's cell is not the other's. Cells, vertices and stamps come from
// per-lane pools topped up between the steps of a round; the bad facets a lane
// finds that it may not refine, and the elements it leaves, are handed over
// after the round, lane by lane. So each lane does exactly what it would do
// alone: one thread runs the lanes one after the other and gets the same
// triangulation, to the byte.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "deadline.h"
#include "lane_cut.h"
#include "level_cells.h"
#include "level_curves.h"
#include "level_facets.h"
#include "morton_blocks.h"
#include "optimize/cone_hole.h"
#include "rdmesh/mesher.h"
#include "restricted_complex.h"
#include "triangulation_walks.h"

namespace rdmesh::detail {

class RefinementLanes {
 public:
  /// All must outlive the lanes. `min_size`: Insertion's guard. `threads`:
  /// MeshOptions::threads (the lanes run on one thread when the cell size may
  /// not be called from several threads: ScalarField::is_concurrent). Facets
  /// go through the lanes too on a `smooth` domain (no curves, no corners)
  /// when the facet size and the facet distance may.
  RefinementLanes(RestrictedComplex& complex, CellLevel& cells, FacetLevel& facets,
                  const CurveLevel& curves, const Criteria& criteria, double min_size, int threads,
                  bool smooth);

  /// Cuts space along its longest axis through the middle of the vertices,
  /// cuts the vertices' box into the blocks of the lanes' cell queues and
  /// turns the cell level's lanes on, and the facet level's (see the
  /// constructor). Before the first cells are queued.
  void start();
  /// Whether a lane has elements queued, or the levels parked some for a round.
  bool pending() const;
  /// One round: a new cut (the axes in turn, see kShortAxis) through the
  /// median of the queued facets' and cells' centres, the lanes' queues shared out again,
  /// then both lanes refine. Stops early at `deadline` (true then).
  bool round(RefinementStats& stats, const Deadline& deadline);

 private:
  struct Lane;
  /// Refines lane `lane`'s queue until it empties, its pools run low or its
  /// step ends (Lane::full then).
  void run(Lane& lane);
  /// Inserts the centre of the lane's facet or cell `e`, or says why not.
  enum class Outcome { kInserted, kDropped, kDeferred, kCrossed, kFull };
  Outcome refine(Lane& lane, const ElementEntry& e);
  /// Inserts `center` (labelled `info`), whose ball has `squared_radius`, when
  /// its conflict zone, found from `start`, is the lane's.
  Outcome insert(Lane& lane, const Point3& center, double squared_radius, Cell_handle start,
                 const VertexInfo& info);
  /// Where an entry's point goes: its surface ball's or Delaunay ball's centre.
  static Point3 centre_of(const ElementEntry& e);

  RestrictedComplex& complex_;
  Triangulation& tr_;
  CellLevel& cells_;
  FacetLevel& facets_;
  const CurveLevel& curves_;
  const Criteria& criteria_;
  double min_size_sq_;
  int threads_;
  bool surface_;
  std::array<int, 3> axes_{0, 1, 2};  ///< by decreasing extent
  int cut_axes_ = 2;                  ///< the rounds' cuts take axes_[0, cut_axes_) in turn
  LaneCut cut_;
  MortonBlocks blocks_;  ///< the blocks of the lanes' cell queues (LaneCellQueue)
  std::size_t rounds_ = 0;
  std::vector<ElementEntry> crossed_;  ///< entries whose zone crossed the last cut
};

}  // namespace rdmesh::detail
