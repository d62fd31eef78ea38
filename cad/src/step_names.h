// STEP files through OpenCASCADE's XCAF reader: the shape as STEPControl_Reader
// gives it, plus the names and colours the file holds. A solid is named after
// its own representation item when no other solid has that name ("PartBody" in a
// one-part file), else its part's product ("nut"), else its assembly instance
// ("NUT::1"); a face after its own name, with its colour (its own, else its
// part's). Entity references ("#1099"), "NONE", empty names and the product name
// OpenCASCADE's writer gives every part are no names.
#pragma once

#include <string>

#include "cad_model.h"

namespace rdmesh::cad {

/// Reads `path` (a STEP file) with names and colours. Throws InputError.
ReadShape read_step_with_names(const std::string& path);

}  // namespace rdmesh::cad
