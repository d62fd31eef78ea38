#include "rdmesh/feature_table.h"

#include <string>

#include "rdmesh/errors.h"

namespace rdmesh {

void throw_unknown_id(const char* kind, int id, std::size_t count) {
  throw OracleError(
      "no " + std::string(kind) + " " + std::to_string(id) + " (" +
      (count == 0 ? std::string("there are none") : "ids 1.." + std::to_string(count)) + ")");
}

}  // namespace rdmesh
