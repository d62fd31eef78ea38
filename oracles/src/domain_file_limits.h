// Limits of the implicit domain file (.json), checked while it is read so that a
// hostile file is refused in well under a second instead of crashing, hanging or
// building an absurd mesh. Each check throws InputError(problem) without the file
// name; the domain-file parser adds it. The values are documented in
// rdmesh/domain_file.h.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rdmesh/geometry.h"
#include "rdmesh/oracle.h"

namespace rdmesh::detail {

inline constexpr int kMaxJsonDepth = 64;                    ///< nested arrays and objects
inline constexpr std::size_t kMaxExpressionLength = 10000;  ///< characters
inline constexpr std::size_t kMaxSubdomains = 64;
inline constexpr std::size_t kMaxCurves = 1000;
inline constexpr std::size_t kMaxPolylinePoints = 100000;
inline constexpr double kMaxCurveLengthInDiagonals = 1000;
/// A curve whose points all lie within this many box diagonals of one another
/// is a point (the implicit oracle's tolerance is 1e-10 diagonals).
inline constexpr double kMinCurveExtentInDiagonals = 1e-10;
inline constexpr double kMaxCurveTurns = 100;

/// Refuses text nesting arrays or objects deeper than kMaxJsonDepth (outside strings
/// and comments), before a DOM is built: nlohmann's DOM recurses on destruction.
void check_json_depth(const std::string& text);

/// Refuses an expression longer than kMaxExpressionLength characters.
void check_expression_length(const std::string& text, const std::string& what);

/// Refuses a box too small or too thin to be meshed in double precision: every
/// extent in [1e-6, 1e12] and at least 1e-6 of the largest extent and of the
/// largest coordinate's magnitude.
void check_box_size(const Box3& box);

/// Refuses a domain that reaches the box: points of a 33 x 33 grid on each face of
/// the box located inside a subdomain ("-1", "sign(x)", a ball larger than its box).
void check_domain_inside_box(const DomainOracle& oracle);

/// Refuses a parametric curve longer than kMaxCurveLengthInDiagonals box diagonals
/// or turning more than kMaxCurveTurns times, measured on an inscribed polygon of
/// 4096 jittered chords (lower bounds of both: 10^6 turns of a circle are refused),
/// and one whose sampled points all lie within kMinCurveExtentInDiagonals of the
/// first (a point: constant expressions, a 't' range below double's resolution).
void check_curve_length(const std::function<Point3(double)>& gamma, double t0, double t1,
                        double diagonal);

/// Refuses a curve that runs over itself (a circle traversed twice, a path going back
/// along itself): at least 4 of 64 points at equal arc length lie within 1e-7 box
/// diagonals of the curve outside their own stretch (one arc-length step each side).
/// A curve crossing itself at isolated points passes.
void check_no_self_overlap(const Curve& curve, double t0, double t1, double diagonal);

/// Refuses two curves that are the same curve: equal length (1e-9 relative) and 7
/// inner points of the first within 1e-7 box diagonals of the second.
void check_distinct_curves(const std::vector<std::pair<std::string, const Curve*>>& curves,
                           const std::vector<std::pair<double, double>>& ranges, double diagonal);

}  // namespace rdmesh::detail
