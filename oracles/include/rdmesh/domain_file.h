// The implicit domain file (.json): functions, subdomains and criteria hints.
//
// Schema (every key not listed here is an error; // and /* */ comments are allowed):
//   "description": string, optional, ignored (a human note about the domain).
//   "bbox": [xmin, ymin, zmin, xmax, ymax, zmax], required, min < max on each axis.
//   "functions": { "name": "expression of x, y, z", ... }, required, non-empty;
//       each function is negative inside (syntax: rdmesh/expression.h).
//   "subdomains": [ { "name": string (optional), "inside": [function names],
//       "outside": [function names] }, ... ], optional when there is exactly one
//       function (its inside is subdomain 1). A subdomain is where its inside
//       functions are < 0 and its outside functions >= 0; the first match wins.
//       "inside"/"outside" may also be a single name string.
//   "curves": [ ... ], optional: sharp features (curves L; corners Q are their
//       endpoints and meeting points), each an object with an optional "name"
//       (non-empty, unique; default "curve_<i>") and either
//         "x", "y", "z": expressions of the single variable t, and
//         "t": [t0, t1], finite, t0 < t1 (closed when the ends coincide), or
//         "points": [[x, y, z], ...], at least two distinct points, a polyline
//         parameterised by arc length (closed when first == last).
//       Every curve must lie in the box and on the domain boundary (two labels
//       around it); see rdmesh/implicit_oracle.h for splitting and corners.
//       Errors read "ORIGIN: curve 'NAME': problem".
//   Criteria hints (defaults that command-line options override):
//   "size", "edge_size", "facet_size", "cell_size": positive number, or expression of x, y, z
//       that must be positive and finite at the box center;
//   "facet_distance", "radius_edge": positive finite numbers;
//   "facet_angle": degrees, in (0, 60) here; criteria above 30 are refused (Criteria::validate).
//   "sizes": an object of sizes per entity, "grade" and "curvature", as a sizing
//       file writes them (rdmesh/size_spec.h), e.g. {"patch:1": 0.05,
//       "curve:rim": 0.02, "subdomain:2": 0.1, "grade": 1.3, "curvature": 12};
//       entities are resolved when the sizes are applied (rdmesh/entity_sizes.h).
//
// Limits (oracles/src/domain_file_limits.h): nesting at most 64 deep (checked on the
// raw text), expressions at most 10000 characters, at most 64 subdomains, 1000 curves,
// 100000 polyline points; bbox extents in [1e-6, 1e12] and at least 1e-6 of the largest
// extent and of the coordinates' magnitude; no point of the box's faces inside the
// domain; parametric curves at most 1000 box diagonals long and 100 turns; no
// duplicate curves. (The CLI also samples size expressions over the whole box.)
//
// Every error is an InputError whose what() is one line "ORIGIN: problem".
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include "rdmesh/geometry.h"
#include "rdmesh/implicit_oracle.h"
#include "rdmesh/oracle.h"
#include "rdmesh/size_spec.h"

namespace rdmesh {

/// Criteria keys found in the file; absent keys are nullopt.
struct CriteriaHints {
  std::optional<ScalarField> size, edge_size, facet_size,
      cell_size;  ///< constant or expression of x,y,z
  std::optional<double> facet_distance, facet_angle, radius_edge;
  std::optional<SizeSpec> sizes;  ///< the "sizes" object
};

struct LoadedDomain {
  std::unique_ptr<DomainOracle> oracle;  ///< an ImplicitOracle
  CriteriaHints hints;
};

/// Reads and parses the file at `path` (messages are prefixed with `path`).
/// Throws InputError when the file cannot be read or is invalid.
LoadedDomain load_domain_file(const std::string& path);

/// Parses the JSON `text`; `origin` (usually the file name) prefixes every message.
/// Throws InputError.
LoadedDomain parse_domain_json(const std::string& text, const std::string& origin);

/// Functions and curves given as code instead of text (the Python module's
/// callables). Only parse_domain_json's third argument accepts them: there a
/// function's value may be {"external": "KEY"} instead of an expression, and a
/// curve may be {"name": ..., "external": "KEY"} instead of "x"/"y"/"z"/"t" or
/// "points"; KEY names an entry below. Every other rule of the file applies
/// (limits, the box check, curve lengths and overlaps). Domain files never
/// accept them.
struct ExternalFunction {
  ImplicitOracle::Function point;              ///< required
  ImplicitOracleOptions::BatchFunction batch;  ///< optional: the box sampling's grid at once
};

struct ExternalDefinitions {
  std::map<std::string, ExternalFunction> functions;
  std::map<std::string, ImplicitCurveSpec> curves;  ///< the spec's name is the document's
};

LoadedDomain parse_domain_json(const std::string& text, const std::string& origin,
                               const ExternalDefinitions& external);

}  // namespace rdmesh
