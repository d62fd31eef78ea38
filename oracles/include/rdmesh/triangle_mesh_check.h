// Structural checks of a triangle mesh: edges, orientation, self-intersections.
//
// A volume mesher needs closed, manifold, consistently oriented surfaces that do
// not cut themselves; these functions establish that (or say precisely why not,
// with coordinates at full precision so the problem can be found in the file).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "rdmesh/triangle_mesh_io.h"

namespace rdmesh {

/// Edge adjacency and connected components of an oriented triangle mesh.
struct TriangleMeshTopology {
  /// neighbors[t][k]: the triangle across edge (t[k], t[(k + 1) % 3]), -1 on a border.
  std::vector<std::array<int, 3>> neighbors;
  /// Component of each triangle (edge-connected), numbered 0.. in order of
  /// their first triangle.
  std::vector<int> component;
  int component_count = 0;
  /// Whether each component has no border edge.
  std::vector<bool> component_closed;
};

/// Why a triangle mesh could not be oriented (OrientationResult).
enum class OrientationFailure {
  none,               ///< oriented
  non_manifold_edge,  ///< an edge shared by more than two triangles
  not_closed,         ///< a border edge, when a closed mesh was required
  non_orientable,     ///< a component with no consistent orientation (a Moebius-like band)
};

/// The outcome of try_orient_triangle_mesh: the topology when oriented, else
/// the failure and its description ("problem", without a file name).
struct OrientationResult {
  OrientationFailure failure = OrientationFailure::none;
  std::string problem;
  TriangleMeshTopology topology;
  bool ok() const { return failure == OrientationFailure::none; }
};

/// Connects the triangles across their edges and orients each component
/// consistently, closed components with their normals pointing out (positive
/// enclosed volume): triangles are flipped in place (swapping their last two
/// corners). On failure (an edge shared by more than two triangles, a
/// non-orientable component, and when `require_closed`, a border edge) the
/// soup is left as it was and the result says why.
OrientationResult try_orient_triangle_mesh(TriangleSoup& soup, bool require_closed);

/// try_orient_triangle_mesh for a mesh read from `file`: throws InputError
/// "FILE: problem" ("non-manifold edge ...", "non-orientable surface ...",
/// "not closed: ...") on failure.
TriangleMeshTopology orient_triangle_mesh(TriangleSoup& soup, const std::string& file,
                                          bool require_closed);

/// Throws InputError "FILE: self-intersecting: triangles I and J ..." when two
/// triangles meet other than along their shared edge or at their shared vertex
/// (exact predicates; touching counts as intersecting).
void check_self_intersections(const TriangleSoup& soup, const std::string& file);

/// The volume enclosed by the oriented closed triangles of `soup` (divergence theorem).
double enclosed_volume(const TriangleSoup& soup);

}  // namespace rdmesh
