// The CAD layer linked into the program (the Python module, the tests, the
// C++ package): always there, nothing to load.
#include "cad_run_layer.h"

namespace rdmesh::run {

const CadLayer& cad_layer() { return cad_run_layer(); }

const CadLayer* loaded_cad_layer() { return &cad_run_layer(); }

}  // namespace rdmesh::run
