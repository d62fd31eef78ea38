// The oracle conformance suite: properties every DomainOracle must have
// (implicit functions, triangle meshes, CAD models and the samples' custom oracles).
#pragma once

#include "rdmesh/oracle.h"

namespace rdmesh {

/// Checks, with GoogleTest EXPECT macros (so a test reports every violation):
/// - the bounding box is finite and non-empty, tolerance() is positive and small;
/// - subdomains() are 1..n in order, patches() have ascending unique ids and
///   sides 0 <= side_a < side_b <= n;
/// - locate() is kOutside outside the box and in 0..n inside;
/// - locate() without a hint returns no crossing; with the label of the other
///   end of a random segment as hint it returns the same label, deterministically,
///   and any crossing it returns is a valid hit of that segment (as intersect()'s);
/// - on `samples` random segments (long and short) in the box: when the end
///   labels differ intersect() returns a point on the segment, the labels at
///   +-4 tolerance() along the segment differ and are the hit's patch sides, and
///   the patch is listed; when they are equal any returned hit is as valid;
///   answers are deterministic;
/// - every listed patch has >= 3 initial points, each on the patch: project()
///   returns it back, and the labels across the surface at it are the patch sides;
/// - project() of perturbed initial points lands on the patch, near the original;
/// - the sharp features pass expect_feature_conformance (unless `with_features` is false).
void expect_oracle_conformance(const DomainOracle& oracle, int samples = 2000, unsigned seed = 1,
                               bool with_features = true);

/// Checks the curves and corners (feature_conformance.cpp):
/// - curve ids 1..n, corner ids 1..m; a closed curve has corners 0, an open one
///   valid corners that list it; every corner lists only curves ending there;
/// - each open curve's end points are its corners' points (within tolerance());
/// - each curve's patches are listed, and at 8 points of the curve the labels on
///   a small circle in the normal plane include both sides of each; likewise on
///   a small sphere around each corner for the corner's patches;
/// - length is additive, parameter_at_length inverts it, closest returns a
///   point at least as close as a known one, plane_crossings lie on the plane
///   and find the crossing through a chosen curve point;
/// - curves meet only at corners; curve(0) and curve(n + 1) throw OracleError.
void expect_feature_conformance(const DomainOracle& oracle, unsigned seed = 1);

}  // namespace rdmesh
