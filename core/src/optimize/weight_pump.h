// Private to core/: one step of sliver exudation [CDE+00], pumping the weight
// of one vertex of the regular triangulation while the restricted complex
// stays exactly as it is.
//
// Raising the weight w of vertex v (its position is fixed) grows its star:
// a cell c that is not incident to v joins the conflict zone of (v, w) when
// w passes the critical weight crit(c) = |v - z_c|^2 - r_c^2, the power of v
// with respect to c's orthosphere (center z_c, squared radius r_c^2). The
// star at weight w is the cone from v over the boundary of the zone
// Z(w) = {cells of the star of v} + {cells reachable from it with crit < w}.
// Between two consecutive critical weights the star, hence its quality, is
// constant: the candidates are these intervals, up to the weight bound.
//
// A candidate zone Z is valid when
//  - every vertex of Z other than v stays on its boundary (none is hidden);
//  - no restricted facet (D|S) disappears: Z never absorbs a cell across a
//    restricted facet, and each restricted facet (v, a, b) of the old star
//    keeps its edge ab on the boundary of Z (so (v, a, b) is a facet of the
//    new star); no edge of D|L (ChainEdges; without them, no edge joining two
//    feature vertices, dim <= 1) is lost;
//  - labels stay consistent: a new cell takes the label of its outer
//    neighbour across a non-restricted boundary facet, the label of the old
//    cell it replaces across a restricted one, and two new cells sharing a
//    facet (v, a, b) have equal labels unless (v, a, b) was restricted (then
//    they carry the facet's two labels);
//  - every new finite cell is positively oriented (exact predicate);
//  - optionally, new domain cells satisfy the cell rules R5.1 / R5.2 of the
//    criteria (CellLimits), so that the output still meets them.
// Among valid candidates the one whose new domain cells (label != 0) have the
// largest smallest dihedral angle wins, if it is strictly larger than the
// smallest dihedral angle of the domain cells of Z it replaces. The chosen
// weight is checked once more with the exact, perturbed power test (every
// cell of Z in conflict with the new weighted point, no cell next to Z: then
// Z is exactly what CGAL's find_conflicts would return) before the zone is
// re-triangulated in place (the vertex object is kept, see cone_hole.h).
//
// In a lane (set_lane()), a pump reads and writes only the cells its lane
// owns: those whose finite vertices all carry the lane's number
// (VertexInfo::lane; the infinite vertex carries every lane or none, as the
// exuder decides). A star, zone or zone neighbour outside the lane, or a
// cone needing more cells than the hole and the lane's pool hold, leaves the
// vertex as it is (kDeferred) for a pass that sees the whole triangulation.
#pragma once

#include <array>
#include <cstdint>
#include <queue>
#include <vector>

#include "../triangulation_types.h"
#include "../triangulation_walks.h"
#include "chain_edges.h"
#include "cone_hole.h"
#include "edge_table.h"
#include "exudation_lanes.h"
#include "rdmesh/criteria.h"

namespace rdmesh::detail {

/// Cell rules the new domain cells must keep (nullptr criteria: none).
struct CellLimits {
  const Criteria* criteria = nullptr;
  bool size = false;         ///< R5.1: circumradius <= cell_size(circumcenter)
  bool radius_edge = false;  ///< R5.2: circumradius <= cell_radius_edge * shortest edge
};

class WeightPump {
 public:
  enum class Outcome {
    kAccepted,       ///< the weight changed; new_cells() is the new star
    kNoImprovement,  ///< no valid weight below the bound improves the star
    kInexact,        ///< the best weight's exact conflict zone differed from the estimate
    kDeferred,       ///< it needs cells outside the pump's lane (or more pooled cells)
  };

  /// `first_stamp`: the stamp given to the first cell this pump creates.
  /// `chains`: the edges of D|L to keep; null keeps every edge joining two
  /// feature vertices (dim <= 1).
  WeightPump(Triangulation& tr, std::uint32_t first_stamp, CellLimits limits = {},
             const ChainEdges* chains = nullptr);

  /// From now on, work inside lane `lane` only, taking cells from `pool`; -1
  /// (the default): everywhere, with the triangulation's container.
  /// Its new cells' stamps then are first_stamp, first_stamp + stamp_stride, ...
  /// (one sequence per lane).
  void set_lane(int lane, CellPool* pool, std::uint32_t first_stamp, std::uint32_t stamp_stride) {
    lane_ = lane;
    pool_ = pool;
    next_stamp_ = first_stamp;
    stamp_stride_ = stamp_stride;
  }
  /// Whether cell c lies in the pump's lane (always, without one).
  bool in_lane(Cell_handle c) const { return lane_ < 0 || detail::in_lane(c, lane_); }

  /// Tries weights of `v` in (current weight, max_weight]; applies the best one.
  /// `star`, when given: the cells around v as Triangulation::incident_cells
  /// lists them, with `star_cosine` the worst cosine of its domain cells
  /// (the caller has them already).
  Outcome pump(Vertex_handle v, double max_weight, const std::vector<Cell_handle>* star = nullptr,
               double star_cosine = 0);

  /// The cells created by the last accepted pump (the star of its vertex).
  const std::vector<Cell_handle>& new_cells() const { return new_cells_; }

  std::uint32_t next_stamp() const { return next_stamp_; }

 private:
  struct Frontier {
    double crit;
    Cell_handle cell;
    bool operator>(const Frontier& o) const { return crit > o.crit; }
  };
  /// A facet of the boundary of Z and the cell that will replace Z behind it.
  struct BoundaryFacet {
    Cell_handle inner;         ///< cell of Z
    int index;                 ///< facet index in `inner`
    int label;                 ///< label of the new cell (v + facet)
    bool infinite;             ///< the facet has the infinite vertex
    std::uint32_t zone_index;  ///< of `inner` in zone_
  };
  /// A restricted facet (v, a, b) of the old star, &*a < &*b.
  struct StarFacet {
    Vertex_handle a, b;
    PatchId patch;
    Point3 center;
    int label0, label1;
  };
  enum class Check { kValid, kInvalid, kInvalidFromNowOn };

  /// False when the star leaves the lane.
  bool collect_star(Vertex_handle v, const std::vector<Cell_handle>* star, double star_cosine);
  void push_frontier(Cell_handle c, Vertex_handle v);
  /// Adds c to Z; false (Z unchanged) when c may never join it.
  bool absorb(Cell_handle c);
  /// Lists the boundary of the current Z with the labels of the new cells and
  /// returns the worst cosine of the new domain cells; stops early (returning
  /// a value >= `cutoff`) as soon as one new domain cell is not better than `cutoff`.
  /// Without `measure`, only lists it (and returns -infinity).
  double boundary_quality(Vertex_handle v, double cutoff, bool measure = true);
  /// Validity of the current Z, whose boundary boundary_quality() listed in full.
  Check validate(Vertex_handle v);
  void clear_marks();
  Outcome commit(Vertex_handle v, double weight);

  /// The new cell v + (a, b, c) keeps the cell rules of limits_.
  bool within_limits(const Point3& v, const Point3& a, const Point3& b, const Point3& c) const;

  Triangulation& tr_;
  std::uint32_t next_stamp_;
  std::uint32_t stamp_stride_ = 1;
  CellLimits limits_;
  const ChainEdges* chains_;
  std::vector<Cell_handle> zone_;  ///< Z: the star of v first, then absorbed cells
  std::size_t star_size_ = 0;
  double zone_quality_ = -1;  ///< worst cosine over the domain cells of Z
  std::vector<StarFacet> star_facets_;
  std::vector<BoundaryFacet> boundary_;
  EdgeTable edges_;                         ///< the boundary edges of the current Z (validate())
  std::vector<std::uint32_t> vertex_mark_;  ///< by VertexInfo::index: == mark_ on the boundary
  std::uint32_t mark_ = 0;
  std::uint32_t infinite_mark_ = 0;
  /// The cells next to Z, lowest critical weight first; keeps its storage
  /// from one pump to the next.
  struct FrontierQueue
      : std::priority_queue<Frontier, std::vector<Frontier>, std::greater<Frontier>> {
    void clear() { c.clear(); }
  };
  FrontierQueue frontier_;
  /// By zone_ index z and facet i (4 z + i): the cosine of the new cell v +
  /// facet i of zone_[z], once computed in this pump.
  std::vector<double> facet_cosine_;
  /// The boundary facet (inner, index) of the last candidate boundary_quality()
  /// rejected, and the cosine of its new cell.
  struct Rejecting {
    Cell_handle inner;
    int index = -1;
    double cosine = 0;
  } rejecting_;
  int lane_ = -1;
  CellPool* pool_ = nullptr;
  bool left_lane_ = false;  ///< push_frontier() met a cell outside the lane
  ConeBuilder cone_;
  std::vector<HoleFacet> hole_facets_;
  std::vector<Cell_handle> new_cells_;
  StarWalk walk_;
};

}  // namespace rdmesh::detail
