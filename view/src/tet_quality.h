// Dihedral angles of the tetrahedra: per tetrahedron the smallest (to find the
// worst elements), and over all of them the extremes and a 5-degree histogram.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "rdmesh/view_mesh.h"

namespace rdmesh::view::detail {

constexpr int kHistogramBins = 36;  ///< [0, 5), [5, 10), ..., [175, 180] degrees

struct TetQuality {
  std::vector<float> min_angle;                         ///< per tetrahedron, degrees
  std::array<std::size_t, kHistogramBins> histogram{};  ///< all six angles of every tetrahedron
  double min = 0, max = 0;  ///< over all angles (0 when there is no tetrahedron)
  std::size_t below = 0;    ///< tetrahedra whose smallest angle is below the threshold
};

/// Measures every tetrahedron; `threshold` (degrees) decides TetQuality::below.
/// A flat tetrahedron has angles of 0 and 180 degrees; a face of zero area
/// gives 0 at its edges.
TetQuality measure_tets(const ViewMesh& mesh, double threshold);

}  // namespace rdmesh::view::detail
