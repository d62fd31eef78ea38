// Internal to oracles/: the parser of rdmesh/size_spec.h on a parsed JSON
// value, shared by sizing files and the domain file's "sizes" key.
#pragma once

#include <nlohmann/json.hpp>

#include "rdmesh/size_spec.h"

namespace rdmesh::detail {

/// Throws InputError (without a file name) naming the offending key.
SizeSpec size_spec_from_json(const nlohmann::ordered_json& object);

}  // namespace rdmesh::detail
