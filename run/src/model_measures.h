// The exact measures of the model behind an oracle, for the fidelity check
// (io's check_fidelity): CAD models and triangle meshes know them.
#pragma once

#include <optional>

#include "rdmesh/fidelity.h"
#include "rdmesh/oracle.h"

namespace rdmesh::run {

/// Volumes per subdomain of a CadOracle (BRepGProp; the mesh's patch areas
/// serve the tolerance), the enclosed volume and the areas per patch of a
/// TriangleMeshOracle; nullopt for other oracles (implicit domains: no exact
/// measure to compare with). With `surface_only`, no volume.
std::optional<ModelMeasures> model_measures(const DomainOracle& oracle, bool surface_only);

}  // namespace rdmesh::run
