// The oracle conformance suite: properties every DomainOracle must have
// (implicit functions today; CAD and triangle meshes later).
#pragma once

#include "rdmesh/oracle.h"

namespace rdmesh {

/// Checks, with GoogleTest EXPECT macros (so a test reports every violation):
/// - the bounding box is finite and non-empty, tolerance() is positive and small;
/// - subdomains() are 1..n in order, patches() have ascending unique ids and
///   sides 0 <= side_a < side_b <= n;
/// - locate() is kOutside outside the box and in 0..n inside;
/// - on `samples` random segments (long and short) in the box: when the end
///   labels differ intersect() returns a point on the segment, the labels at
///   +-4 tolerance() along the segment differ and are the hit's patch sides, and
///   the patch is listed; when they are equal any returned hit is as valid;
///   answers are deterministic;
/// - every listed patch has >= 3 initial points, each on the patch: project()
///   returns it back, and the labels across the surface at it are the patch sides;
/// - project() of perturbed initial points lands on the patch, near the original.
void expect_oracle_conformance(const DomainOracle& oracle, int samples = 2000, unsigned seed = 1);

}  // namespace rdmesh
