// What each fuzz target reads, shared by the libFuzzer targets (fuzz_target.cpp)
// and their regression test (tests/oracles/fuzz_regression_test.cpp): the same
// bytes go through the same library calls in both.
//
// Contract under test: a reader either succeeds or throws rdmesh::InputError.
// Any other exception, a crash, a leak, undefined behaviour or a hang is a bug.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "rdmesh/domain_file.h"
#include "rdmesh/expression.h"
#include "rdmesh/triangle_mesh_io.h"
#include "rdmesh/triangle_mesh_oracle.h"

namespace rdmesh::fuzz {

/// The in-memory readers: "off", "stl", "obj", "ply", "domain_json", "expression".
inline constexpr std::string_view kTargets[] = {"off", "stl",         "obj",
                                                "ply", "domain_json", "expression"};

/// A triangle mesh read as the CLI reads it (read_triangle_mesh without the
/// file), then turned into an oracle twice: as an open surface (orientation,
/// self-intersections, patches, curves and corners) and as a closed domain.
inline void read_mesh(TriangleSoup (*parse)(std::istream&, const std::string&),
                      std::string_view bytes) {
  std::istringstream in{std::string(bytes)};
  TriangleSoup soup = parse(in, "fuzz");
  merge_duplicate_vertices(soup);
  validate_soup(soup, "fuzz");
  TriangleMeshOptions surface;
  surface.surface_only = true;
  TriangleMeshOracle open(soup, "fuzz", surface);
  TriangleMeshOracle closed(std::move(soup), "fuzz");
}

/// An implicit domain file, then one query of its oracle.
inline void read_domain(std::string_view bytes) {
  LoadedDomain domain = parse_domain_json(std::string(bytes), "fuzz");
  const Box3 box = domain.oracle->bounding_box();
  domain.oracle->locate(0.5 * (box.lo + box.hi));
}

/// An expression of x, y, z, evaluated at a few points (NaN and inf are results).
inline void read_expression(std::string_view bytes) {
  const Expression e{std::string(bytes)};
  e(0, 0, 0);
  e(1, -2, 3.5);
  e(-1e300, 1e-300, 0);
}

/// Feeds `bytes` to the reader of `target` (one of kTargets).
inline void read_input(std::string_view target, std::string_view bytes) {
  if (target == "off") return read_mesh(parse_off, bytes);
  if (target == "stl") return read_mesh(parse_stl, bytes);
  if (target == "obj") return read_mesh(parse_obj, bytes);
  if (target == "ply") return read_mesh(parse_ply, bytes);
  if (target == "domain_json") return read_domain(bytes);
  if (target == "expression") return read_expression(bytes);
  throw std::logic_error("unknown fuzz target '" + std::string(target) + "'");
}

}  // namespace rdmesh::fuzz
