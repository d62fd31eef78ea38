// Private to core/: sliver perturbation of volume vertices, after weight
// pumping, on the slivers it could not remove.
//
// A volume vertex v (FeatureDim::kVolume) incident to a sliver is moved along
// the gradient of the smallest dihedral angle of its worst incident domain
// cell, by a fraction of its nearest-neighbour distance. A move from v to p
// (keeping v's weight) destroys exactly the star of v and the cells of the
// triangulation in conflict with the weighted point at p, provided no vertex
// gets hidden (checked: each vertex keeps a cell outside that set). The
// move is tried only when all those cells carry the same label and none has
// a restricted facet: then every new cell gets that label, and the restricted
// facets and labels of the rest are untouched, so D|S stays identical. The
// move is kept when the smallest dihedral angle of the new cells strictly
// exceeds that of the destroyed ones, and undone otherwise (moving back gives
// the same triangulation; its cells get the same label and no restricted facet).
#pragma once

#include <cstdint>
#include <vector>

#include "../triangulation_types.h"

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
  /// Gradient of the smallest dihedral angle (radians) of cell c with v moved; zero if none.
  Point3 angle_gradient(Cell_handle c, Vertex_handle v, double h) const;
  /// The destroyed cells of a move of v to p (star of v + conflicts of p) if
  /// they all carry label `label` and no restricted facet; their worst cosine in `worst`.
  bool movable_to(Vertex_handle v, const Point3& p, int label, double nearest, double& worst);
  /// Moves v to p and initializes the new cells (label `label`); returns their worst cosine.
  double move(Vertex_handle v, const Point3& p, int label);

  Triangulation& tr_;
  std::uint32_t next_stamp_;
  std::vector<Cell_handle> star_;
  std::vector<Cell_handle> conflicts_;
  std::vector<Triangulation::Facet> facets_;
  std::vector<Cell_handle> new_cells_;
  std::vector<Cell_handle> incident_;
};

}  // namespace rdmesh::detail
