// The one implementation of the run's CAD layer (cad_layer.h), for the two
// ways of reaching it: linked (linked_cad_layer.cpp) or in the command's
// module (cad_module_entry.cpp).
#pragma once

#include "rdmesh/cad_layer.h"

namespace rdmesh::run {

/// The CAD layer built on cad/ (OpenCASCADE).
const CadLayer& cad_run_layer();

}  // namespace rdmesh::run
