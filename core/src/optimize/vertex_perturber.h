// Private to core/: sliver perturbation of volume vertices, after weight
// pumping, on the slivers it could not remove.
//
// A volume vertex v (FeatureDim::kVolume) incident to a sliver is moved along
// the gradient of the smallest dihedral angle of its worst incident domain
// cell, by a fraction of its nearest-neighbour distance. A move from v to p
// (keeping v's weight) replaces the region R made of the star of v and the
// cells of the triangulation in conflict with the weighted point at p. It is
// tried only when all those cells carry the same label and none has a
// restricted facet: then every new cell gets that label, and the restricted
// facets and labels of the rest are untouched, so D|S stays identical.
//
// The new cells are the cone from p over the boundary of R, built in place
// (cone_hole, the same vertex object), when that cone is the regular
// triangulation there: the boundary is a closed surface (each edge on two
// facets) holding every vertex of R but v (none gets hidden), every new cell
// is positively oriented, and every facet of a new cell is locally regular
// (an exact power test against the cell across it, strict: a cospherical case
// is not a move, so no symbolic perturbation has to decide). Otherwise the
// move is not made. It is made when the smallest dihedral angle of the new
// cells, computed before anything changes, strictly exceeds that of the
// cells of R. Everything here follows the triangulation's structure, never
// the addresses of cells or vertices, so a move is the same on every run
// (CGAL's move_if_no_collision, used before, refilled the removed vertex's
// hole in the address order of vertex handles).
#pragma once

#include <cstdint>
#include <vector>

#include "../triangulation_types.h"
#include "cone_hole.h"
#include "edge_table.h"

namespace rdmesh::detail {

class VertexPerturber {
 public:
  /// `first_stamp`: the stamp given to the first cell this perturber creates.
  VertexPerturber(Triangulation& tr, std::uint32_t first_stamp);

  /// Tries to move volume vertex `v` (nearest neighbour at distance `nearest`);
  /// true when it moved and the smallest dihedral angle around it rose.
  bool perturb(Vertex_handle v, double nearest);

  /// The cells created by the last successful move.
  const std::vector<Cell_handle>& new_cells() const { return new_cells_; }

  std::uint32_t next_stamp() const { return next_stamp_; }

 private:
  /// A boundary facet of R seen from inside, and the new cell's shape.
  struct BoundaryFacet {
    Cell_handle inner;
    int index;
    Cell_handle outer;  ///< the cell across it, which stays
    int outer_index;    ///< the facet's index in `outer`
  };

  /// Gradient of the smallest dihedral angle (radians) of cell c with v moved; zero if none.
  Point3 angle_gradient(Cell_handle c, Vertex_handle v, double h) const;
  /// Plans the move of v to p: R (region_) and its boundary (boundary_) when
  /// the move is possible (see the file comment), with the worst cosine of the
  /// cells of R in `old_worst` and of the new cells in `new_worst`.
  bool plan_move(Vertex_handle v, const Point3& p, int label, double nearest, double& old_worst,
                 double& new_worst);
  /// The cone over boundary_ is the regular triangulation of R with v at p.
  bool cone_is_regular(Vertex_handle v, const Weighted_point& wp);
  /// Moves v to p (a planned move) and initializes the new cells (label `label`).
  void move(Vertex_handle v, const Point3& p, int label);

  Triangulation& tr_;
  std::uint32_t next_stamp_;
  std::vector<Cell_handle> star_;
  std::vector<Cell_handle> conflicts_;
  std::vector<Triangulation::Facet> facets_;
  std::vector<Cell_handle> region_;  ///< R: the star of v, then the other cells in conflict
  std::vector<BoundaryFacet> boundary_;
  EdgeTable edges_;  ///< the edges of boundary_, with their facets
  std::vector<Vertex_handle> boundary_vertices_;
  std::vector<HoleFacet> hole_facets_;
  ConeBuilder cone_;
  std::vector<Cell_handle> new_cells_;
};

}  // namespace rdmesh::detail
