// Default sizes for CAD models that follow the thickness of slender parts.
#pragma once

#include "rdmesh/cad_layer.h"  // FollowedDefaults
#include "rdmesh/cad_oracle.h"
#include "rdmesh/criteria.h"

namespace rdmesh::run {

/// Where a curved face has less material behind it than twice the size
/// (CadOracle::curved_thickness: a rod, a pin, a tube's wall), the edge, facet
/// and cell sizes near it become half that thickness, growing by kGrading per
/// unit of distance from the face's box, so that the mesh has cells inside the
/// part (cad_sizes.cpp). Returns the number of faces that lowered the sizes.
///
/// What the user did not set follows the thickness too (`defaults`): the facet
/// distance near those faces becomes a tenth of that local size (the default
/// ratio), and in each solid at most a tenth of half its mean thickness 2V/A,
/// so that the boundary follows a rod's section (a hexagon at half the rod's
/// thickness lost 17% of bm2_ec_leverrod's volume) and the fidelity check's
/// tolerance, which follows the facet distance, means something there; the
/// minimum size (1e-4 of the box's diagonal by default) goes down to 1/50 of
/// the thinnest solid's mean thickness (among solids of at least 1e-6 of the
/// model's volume), so that this facet distance can be met.
int follow_thickness(const CadOracle& cad, Criteria& criteria, FollowedDefaults defaults);

}  // namespace rdmesh::run
