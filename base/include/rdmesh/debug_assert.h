// RDMESH_DEBUG_ASSERT(condition, what): an invariant the code relies on, checked
// in builds with RDMESH_DEBUG_CHECKS (CMake option, on in Debug builds; CI's
// sanitizer build runs the whole suite with it) and never run otherwise (the
// condition is compiled but not evaluated). A broken invariant throws
// InternalError naming the file, the line, the condition and `what`: the library
// never aborts, and the CLI reports a bug as exit 3 like any other InternalError.
#pragma once

#include <string>

#include "rdmesh/errors.h"

namespace rdmesh::detail {

/// Throws the InternalError of a failed RDMESH_DEBUG_ASSERT (out of line, so the
/// check itself stays one compare and one branch).
[[noreturn]] void debug_assert_failed(const char* file, int line, const char* condition,
                                      const std::string& what);

}  // namespace rdmesh::detail

#if RDMESH_DEBUG_CHECKS
#define RDMESH_DEBUG_ASSERT(condition, what)                                         \
  do {                                                                               \
    if (!(condition))                                                                \
      ::rdmesh::detail::debug_assert_failed(__FILE__, __LINE__, #condition, (what)); \
  } while (false)
#else
// Compiled (names stay used, a typo still fails the build) but never run.
#define RDMESH_DEBUG_ASSERT(condition, what) \
  do {                                       \
    if (false) {                             \
      static_cast<void>(condition);          \
      static_cast<void>(what);               \
    }                                        \
  } while (false)
#endif
