// The entry point of rdmesh_cad_module.so, the command's CAD layer
// (rdmesh/cad_layer.h): the one symbol the module exports.
#include <cstring>

#include "cad_run_layer.h"

/// The layer, when the command asking is of this module's version (the two
/// come from one build; another version's command could expect another layout
/// of CadLayer); else nullptr.
extern "C" __attribute__((visibility("default"))) const rdmesh::run::CadLayer* rdmesh_cad_layer_v1(
    const char* command_version) {
  if (std::strcmp(command_version, RDMESH_VERSION) != 0) return nullptr;
  return &rdmesh::run::cad_run_layer();
}
