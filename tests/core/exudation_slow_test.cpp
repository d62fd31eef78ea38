// Sliver exudation at the benchmark's sizes (bench/: criteria h, h/10, 25
// degrees, radius-edge 3): the quality it reaches, checked with margins so that
// a regression shows while small changes of refinement do not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mesh_checks.h"
#include "rdmesh/implicit_oracle.h"
#include "rdmesh/mesher.h"

namespace rdmesh {
namespace {

Criteria bench_criteria(double h) {
  Criteria c;
  c.facet_size = c.cell_size = ScalarField::uniform(h);
  c.facet_distance = h / 10;
  c.facet_angle_deg = 25;
  c.cell_radius_edge = 3;
  return c;
}

void expect_good_quality(const DomainOracle& oracle, double h, double min_angle_deg) {
  MeshOptions options;
  options.exudation.self_check = true;
  const MeshResult r = generate_mesh(oracle, bench_criteria(h), options);
  const ExudationStats& s = r.exudation;
  std::printf("exudation h=%g: min dihedral %.2f -> %.2f deg, %zu/%zu moves, %.2f s\n", h,
              s.min_dihedral_before_deg, s.min_dihedral_after_deg, s.moves_accepted, s.moves_tried,
              s.seconds);
  EXPECT_GE(s.min_dihedral_after_deg, min_angle_deg);
  EXPECT_EQ(s.histogram_after[0] + s.histogram_after[1], 0u);  // nothing below 10 degrees
  test::expect_positive_orientation(r.mesh);
  test::expect_conforming(r.mesh);
}

TEST(ExudationSlow, SphereReachesTenDegrees) {
  const ImplicitOracle sphere({{-1.2, -1.2, -1.2}, {1.2, 1.2, 1.2}},
                              {[](const Point3& p) { return squared_norm(p) - 1.0; }});
  expect_good_quality(sphere, 0.05, 10.0);
}

TEST(ExudationSlow, TorusReachesTenDegrees) {
  const ImplicitOracle torus({{-1.6, -1.6, -0.6}, {1.6, 1.6, 0.6}}, {[](const Point3& p) {
                               const double q = std::sqrt(p.x * p.x + p.y * p.y) - 1.0;
                               return q * q + p.z * p.z - 0.35 * 0.35;
                             }});
  expect_good_quality(torus, 0.05, 10.0);
}

}  // namespace
}  // namespace rdmesh
