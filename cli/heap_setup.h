// The command's heap setup (heap_setup.cpp): huge pages for its one big region.
#pragma once

namespace rdmesh::cli {

/// Call first thing in main(); does nothing where it cannot apply.
void setup_heap();

}  // namespace rdmesh::cli
