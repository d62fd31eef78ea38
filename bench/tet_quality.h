// Shape metrics of tetrahedra, computed the same way for rdmesh and the CGAL anchor.
// Plain arrays only: no CGAL, no rdmesh types.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace rdmesh_bench {

using Vec3 = std::array<double, 3>;
using Tet = std::array<int, 4>;

/// Metrics of one tetrahedron.
struct TetShape {
  double min_dihedral_deg = 0;  ///< smallest of the six interior dihedral angles
  double max_dihedral_deg = 0;  ///< largest of the six interior dihedral angles
  double radius_edge = 0;       ///< circumradius / shortest edge (inf for a flat tet)
  double signed_volume = 0;     ///< > 0 when dot(b - a, cross(c - a, d - a)) > 0
};

TetShape tet_shape(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Aggregate over a mesh.
struct MeshQuality {
  std::size_t tets = 0;
  double min_dihedral_deg = 180;
  double max_dihedral_deg = 0;
  double max_radius_edge = 0;
  double volume = 0;             ///< sum of |volume|
  std::size_t non_positive = 0;  ///< tets with signed volume <= 0 (orientation check)
  std::size_t below_10_deg = 0;  ///< tets whose smallest dihedral angle is < 10 degrees
};

/// `tets` index into `vertices` (0-based). Orientation only affects `non_positive`.
MeshQuality mesh_quality(const std::vector<Vec3>& vertices, const std::vector<Tet>& tets);

}  // namespace rdmesh_bench
