// Sizes by curvature (--curvature N, the "curvature" key of a sizing object):
// at least N elements per full turn on curved patches and curves, like Gmsh's
// -clcurv. Requested through SizeRequests::curvature (rdmesh/entity_sizes.h).
//
// Where the radius of curvature is R (DomainOracle::curvature on patches, the
// largest principal curvature; Curve::curvature on curves: the oracles' own
// geometry), the size is pi R / N, a Delaunay-ball radius like every size of
// Criteria: an edge of a restricted facet, of a curve or of a tetrahedron
// whose ball meets its bound is at most that ball's diameter, 2 pi R / N, so a
// circle of radius R gets at least N edges. Sizes below the minimum size
// (Criteria::min_size_for) are clamped to it and counted.
//
// Sampling. Along each curve, a point every half of the local size (the
// curvature's or the edge size, the smaller). On patches, the triangles of a
// first surface-only mesh at the base sizes (the one the entity sizes use):
// curvature at their vertices and centroids, a triangle split in four while
// its sizes differ by more than 25% and it is longer than twice the smallest
// (5 levels at most); a patch without triangles is sampled at its initial
// points. Each segment or triangle takes the smallest size of its samples
// (a triangle, a chord off the patch by its sag d, at most the facet distance
// and L^2 / 8R for its longest edge L, minus (grade - 1) d, so that the size
// holds on the patch), and those whose size
// is not below the base size there are dropped. The
// sizes grow by grade - 1 per unit of distance from the pieces, as entity
// sizes do, and lower the edge, facet and cell sizes by a minimum.
#pragma once

#include <cstddef>

#include "rdmesh/oracle.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh {

/// What sampling the curvature found.
struct CurvatureStats {
  double per_turn = 0;      ///< N; 0 when not asked
  std::size_t samples = 0;  ///< curvature queries
  std::size_t unknown = 0;  ///< queries the oracle could not answer (nullopt)
  std::size_t clamped = 0;  ///< samples whose size pi R / N was below the minimum size
  std::size_t pieces = 0;   ///< segments and triangles that lower the sizes
  double min_radius = 0;    ///< smallest radius of curvature met (0: nothing curved)
  double min_size = 0;      ///< smallest size set (after clamping; 0: none set)
};

/// What a mesh achieved against the curvature sizes: edge lengths over the
/// target 2 pi R / N, R at the edge's middle (curve edges, by the curve's
/// closest parameter) or at a boundary triangle's centroid (its longest
/// edge), counting only where the target is above twice the minimum size.
struct CurvatureAchieved {
  std::size_t curve_edges = 0, curve_over = 0;  ///< measured; longer than the target
  double curve_max_ratio = 0;
  std::size_t facets = 0, facets_over = 0;
  double facet_max_ratio = 0, facet_mean_ratio = 0;
};
CurvatureAchieved achieved_curvature(const TetMesh& mesh, const DomainOracle& oracle,
                                     double per_turn, double min_size);

}  // namespace rdmesh
