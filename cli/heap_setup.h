// The command's heap setup (heap_setup.cpp): huge pages as it grows, and a
// thread that faults it in ahead of the program when the run has the cores.
#pragma once

#include <cstdint>

namespace rdmesh::cli {

/// Call first thing in main(); does nothing where it cannot apply.
void setup_heap();
/// After setup_heap(), for a run given more than one core: a thread faults in
/// the heap's next pages ahead of the program. Does nothing where it cannot apply.
void start_heap_populator();

// For tests: where the heap's next blocks begin (the highest end of a block
// operator new took from it), how far the populating thread has faulted the
// heap in (0: not yet, or no thread), whether the kernel refused, and whether
// the thread runs in the idle scheduling class.
std::uintptr_t heap_frontier();
std::uintptr_t heap_populated_end();
bool heap_populator_refused();
bool heap_populator_idle();

}  // namespace rdmesh::cli
