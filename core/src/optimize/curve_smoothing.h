// Private to core/: moves of a vertex inside one chain of feature edges along
// its curve, for local improvement.
//
// The worst tetrahedra left by the other steps have two or more vertices on
// sharp curves. A vertex between two feature edges of one curve (not a
// corner) may slide along the curve between its two chain neighbours: trial
// positions are points of the exact curve (Curve::point), and a position is
// kept under the conditions of a move along a patch (patch_smoothing.h):
// every tetrahedron around it positive and their smallest angle strictly
// higher, its triangles' normals within kMaxNormalTurnDeg of the input's,
// their samples within the facet distance of their own patches; and the
// midpoints of its two feature edges within the facet distance of the curve,
// and each feature edge at most twice the edge size at its midpoint (R2), or
// no longer than before where it was longer already.
#pragma once

#include <vector>

#include "patch_smoothing.h"
#include "tet_topology.h"

namespace rdmesh::detail {

/// Moves vertex v (surface.curve_of(v) != 0) along its curve to raise the
/// smallest dihedral angle of its tetrahedra; true when it moved.
/// `parameters`: the curve parameter of each vertex inside a chain, NaN until
/// found (grown as needed; kept up to date as vertices move).
bool smooth_on_curve(TetTopology& topo, const PatchSurface& surface,
                     std::vector<double>& parameters, int v);

}  // namespace rdmesh::detail
