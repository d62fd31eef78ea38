// Default sizes for CAD models that follow the thickness of slender parts.
#pragma once

#include "rdmesh/cad_oracle.h"
#include "rdmesh/criteria.h"

namespace rdmesh::cli {

/// Where a curved face has less material behind it than twice the size
/// (CadOracle::curved_thickness: a rod, a pin, a tube's wall), the edge, facet
/// and cell sizes near it become half that thickness, growing by kGrading per
/// unit of distance from the face's box, so that the mesh has cells inside the
/// part (cad_sizes.cpp). Returns the number of faces that lowered the sizes.
int follow_thickness(const CadOracle& cad, Criteria& criteria);

}  // namespace rdmesh::cli
