#include "rdmesh/debug_assert.h"

#include <string>

namespace rdmesh::detail {

void debug_assert_failed(const char* file, int line, const char* condition,
                         const std::string& what) {
  throw InternalError(std::string("invariant broken at ") + file + ":" + std::to_string(line) +
                      ": " + condition + " (" + what + ")");
}

}  // namespace rdmesh::detail
