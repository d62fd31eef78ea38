// --heal: OpenCASCADE's ShapeFix_Shape on the read shape, and what it changed in
// words: the entities it replaced or removed, the fixes it made (counted by
// kind), the largest tolerance before and after, the counts before and after.
// The names and colours read from the file follow the faces and solids healing
// replaced.
#pragma once

#include <string>

#include "cad_model.h"

namespace rdmesh::cad {

/// Heals r.shape in place and appends to r.log what changed. Throws InputError.
void heal_shape(ReadShape& r, const std::string& path);

}  // namespace rdmesh::cad
