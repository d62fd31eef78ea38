// A TetMesh as the picture library sees it (view/include/rdmesh/view_mesh.h).
#pragma once

#include "rdmesh/tet_mesh.h"
#include "rdmesh/view_mesh.h"

namespace rdmesh {

/// The same points and elements with their labels as plain integers
/// (subdomain, patch, curve ids), and the subdomain names.
view::ViewMesh to_view_mesh(const TetMesh& mesh);

}  // namespace rdmesh
