// rdmesh run on the benchmark domains (the side measured against the CGAL anchor).
#pragma once

#include <cstddef>
#include <string>

struct RdmeshResult {
  std::size_t tets = 0;      ///< tetrahedra of the output mesh
  std::size_t vertices = 0;  ///< vertices of the output mesh
  double seconds = 0;        ///< wall time of generate_mesh only
  double setup_seconds = 0;  ///< wall time of the ImplicitOracle constructor (box sampling)
  double min_dihedral_deg = 0;
  double max_radius_edge = 0;
  double volume = 0;                 ///< total volume of the tetrahedra, a sanity check
  std::size_t non_positive = 0;      ///< tetrahedra that are not positively oriented (expected 0)
  std::size_t guard_rejections = 0;  ///< RefinementStats::guard_rejections
  std::size_t below_10_deg = 0;      ///< tets with a dihedral angle < 10 degrees
  // --optimize only (exudation on):
  double min_dihedral_before_deg = 0;   ///< before exudation (ExudationStats)
  std::size_t below_10_deg_before = 0;  ///< before exudation (ExudationStats histogram)
  double refine_seconds = 0;            ///< generate_mesh minus exudation
  double optimize_seconds = 0;          ///< exudation (ExudationStats::seconds)
};

namespace rdmesh {
struct MeshResult;
}

/// The measures of a finished run (`seconds`: its wall time).
RdmeshResult measure_rdmesh(const rdmesh::MeshResult& result, double seconds);

/// Meshes `shape` ("sphere" | "torus", see shapes.h) with rdmesh::generate_mesh and
/// the same criteria as run_cgal_anchor; sliver exudation only when `optimize`.
/// Throws std::invalid_argument for an unknown shape.
RdmeshResult run_rdmesh(const std::string& shape, double h, bool optimize = false);
