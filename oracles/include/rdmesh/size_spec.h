// Sizes asked in a JSON object, as a sizing file (--sizes FILE.json) and the
// "sizes" key of an implicit domain file write them; one parser for both:
//
//   "KIND:WHICH": SIZE  a size on or in one entity, resolved against the
//                       oracle by rdmesh/entity_sizes.h (KIND face, curve or
//                       solid; WHICH an id or a name);
//   "grade": G          how fast those sizes grow away from their entity, > 1;
//   "curvature": N      at least N elements per full turn on curved patches
//                       and curves (rdmesh/curvature_sizes.h), > 0.
//
// Every value is a positive finite number; every key without a colon other
// than "grade" and "curvature" is an error.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rdmesh {

struct SizeSpec {
  std::vector<std::pair<std::string, double>> entities;  ///< ("face:12", 0.5), in file order
  std::optional<double> grade;
  std::optional<double> curvature;
};

/// Parses the JSON object `text` (comments allowed). Throws InputError "ORIGIN: problem".
SizeSpec parse_size_spec(const std::string& text, const std::string& origin);

/// Reads and parses the file at `path`. Throws InputError naming it.
SizeSpec read_size_spec(const std::string& path);

}  // namespace rdmesh
