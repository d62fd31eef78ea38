// CGAL Mesh_3 with 1D features (protecting balls along polylines), the anchor
// of the sharp-features benchmark. Plain header: no CGAL here.
#pragma once

#include <string>

#include "tet_quality.h"

namespace rdmesh_bench {

struct FeatureAnchorResult {
  MeshQuality quality;
  std::size_t vertices = 0;
  double seconds = 0;  ///< make_mesh_3 only
};

/// Meshes "capped_cylinder" (r = 0.5, |z| < 0.6, two rim circles) or "cube"
/// ([-0.5, 0.5]^3, twelve edges) with edge size = facet size = cell size = h,
/// facet distance h / 10, facet angle 25, radius-edge 3; `optimize` adds
/// perturb() and exude() (default time limits), else no perturb, no exude.
FeatureAnchorResult run_cgal_features(const std::string& shape, double h, bool optimize);

}  // namespace rdmesh_bench
