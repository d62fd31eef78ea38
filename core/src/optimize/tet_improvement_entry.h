// Private to core/: improve_tets (rdmesh/tet_improvement.h) for a mesh whose
// tetrahedra's shapes are already known, as generate_mesh has them after
// exudation (Refiner::extract_mesh).
#pragma once

#include <vector>

#include "rdmesh/tet_improvement.h"

namespace rdmesh::detail {

/// improve_tets, with `cosines` the max_dihedral_cosine of each of
/// mesh.tets (optimize/tet_shape.h), or empty: the shapes are computed here.
TetImprovementStats improve_tets_of_known_shape(TetMesh& mesh, const TetImprovementOptions& options,
                                                const BoundarySurface& surface,
                                                std::vector<double> cosines);

}  // namespace rdmesh::detail
