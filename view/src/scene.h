// The two views of the picture: the boundary surface, and the cut through the
// tetrahedra. Both draw into a supersampled Canvas through the same Camera
// (moved to their panel).
#pragma once

#include <array>
#include <vector>

#include "camera.h"
#include "canvas.h"
#include "palette.h"
#include "rdmesh/picture.h"
#include "rdmesh/view_mesh.h"
#include "tet_quality.h"

namespace rdmesh::view::detail {

/// The triangles of the left view: the mesh's own, or when it has none the
/// faces of its tetrahedra that belong to one tetrahedron only, labelled by
/// that tetrahedron's subdomain.
struct Surface {
  std::vector<std::array<int, 3>> derived;
  std::vector<int> derived_labels;
  const std::vector<std::array<int, 3>>* triangles = nullptr;
  const std::vector<int>* labels = nullptr;
  bool from_tets = false;
};
Surface boundary_surface(const ViewMesh& mesh);

/// Line widths and sizes in canvas pixels (the supersampling factor times
/// the final pixels).
struct Strokes {
  float element_edge;  ///< sides of triangles and tetrahedra
  float feature;       ///< sharp curves
  float corner;        ///< corner dot radius
};

/// Left view: the surface flat-shaded by label, its triangles' sides, the
/// sharp curves and the corners.
void draw_surface_view(Canvas& canvas, const Camera& camera, const ViewMesh& mesh,
                       const Surface& surface, const Strokes& strokes);

/// Right view: what lies behind `cut` (the half-space away from the viewer):
/// the faces of the tetrahedra whose centroid is there, coloured by subdomain
/// or in kHighlight when their smallest dihedral angle is below `sliver_angle`,
/// the sharp curves, and a kHighlight ring on top at each such tetrahedron
/// (seen or hidden); without tetrahedra, the surface's triangles there.
void draw_cut_view(Canvas& canvas, const Camera& camera, const ViewMesh& mesh,
                   const Surface& surface, const CutPlane& cut, const TetQuality& quality,
                   double sliver_angle, const Strokes& strokes);

}  // namespace rdmesh::view::detail
