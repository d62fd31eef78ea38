// Smooth implicit test domains and uniform criteria shared by the core tests.
#pragma once

#include <cmath>

#include "rdmesh/criteria.h"
#include "rdmesh/implicit_oracle.h"

namespace rdmesh::test {

/// Edge, facet and cell size h, facet distance h / 10, facet angle 25, radius-edge 2.
inline Criteria uniform_criteria(double h) {
  Criteria c;
  c.edge_size = c.facet_size = c.cell_size = ScalarField::uniform(h);
  c.facet_distance = h / 10;
  c.facet_angle_deg = 25;
  c.cell_radius_edge = 2;
  return c;
}

inline ImplicitOracle unit_sphere() {
  return ImplicitOracle({{-1.2, -1.2, -1.2}, {1.2, 1.2, 1.2}},
                        {[](const Point3& p) { return squared_norm(p) - 1.0; }});
}

/// Torus around the z axis, major radius 1, minor radius 0.35.
inline double torus(const Point3& p) {
  const double q = std::sqrt(p.x * p.x + p.y * p.y) - 1.0;
  return q * q + p.z * p.z - 0.35 * 0.35;
}

/// Subdomain 1: the ball of radius 0.5 ("core"); 2: the shell up to radius 1.
inline ImplicitOracle nested_spheres() {
  return ImplicitOracle({{-1.2, -1.2, -1.2}, {1.2, 1.2, 1.2}},
                        {[](const Point3& p) { return squared_norm(p) - 0.25; },
                         [](const Point3& p) { return squared_norm(p) - 1.0; }},
                        {{"core", {0}, {}}, {"shell", {1}, {0}}});
}

}  // namespace rdmesh::test
