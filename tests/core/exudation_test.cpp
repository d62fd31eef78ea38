// Sliver exudation (RR-7912 section 6): the mesh with exudation against the
// same run without it. Exudation must keep the boundary (the restricted
// facets, with their patches) and the labelled regions exactly, never lower
// the smallest dihedral angle, and leave a valid regular triangulation
// (ExudationOptions::self_check runs tr.is_valid() and the facet/label checks).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <set>
#include <tuple>

#include "capped_cylinder_oracle.h"
#include "mesh_checks.h"
#include "rdmesh/errors.h"
#include "rdmesh/implicit_oracle.h"
#include "rdmesh/mesh_measures.h"
#include "rdmesh/mesher.h"
#include "test_domains.h"

namespace rdmesh {
namespace {

using test::nested_spheres;
using test::torus;
using test::uniform_criteria;
using test::unit_sphere;

using Triangle = std::tuple<std::array<double, 9>, int>;  ///< sorted corner coordinates, patch

/// The labelled triangles as coordinates (vertex numbering differs between runs).
std::set<Triangle> triangle_set(const TetMesh& mesh) {
  std::set<Triangle> out;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::array<Point3, 3> p;
    for (int k = 0; k < 3; ++k) p[k] = mesh.vertices[mesh.triangles[t][k]];
    std::sort(p.begin(), p.end(), [](const Point3& a, const Point3& b) {
      return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    });
    std::array<double, 9> key;
    for (int k = 0; k < 3; ++k) {
      key[3 * k] = p[k].x;
      key[3 * k + 1] = p[k].y;
      key[3 * k + 2] = p[k].z;
    }
    out.insert({key, mesh.triangle_patch[t].value});
  }
  return out;
}

/// Smallest dihedral angle of the mesh, from the io layer's measure (independent of the core's).
using Edge = std::tuple<std::array<double, 6>, int>;  ///< sorted end coordinates, curve

/// The feature edges as coordinates.
std::set<Edge> edge_set(const TetMesh& mesh) {
  std::set<Edge> out;
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    Point3 a = mesh.vertices[mesh.edges[e][0]], b = mesh.vertices[mesh.edges[e][1]];
    if (std::tie(b.x, b.y, b.z) < std::tie(a.x, a.y, a.z)) std::swap(a, b);
    out.insert({{a.x, a.y, a.z, b.x, b.y, b.z}, mesh.edge_curve[e].value});
  }
  return out;
}

double min_dihedral_deg(const TetMesh& mesh) {
  double worst = 180;
  for (const auto& t : mesh.tets) {
    const auto& v = mesh.vertices;
    for (double a : dihedral_angles_deg(v[t[0]], v[t[1]], v[t[2]], v[t[3]]))
      worst = std::min(worst, a);
  }
  return worst;
}

struct Runs {
  MeshResult off, on;
};

/// Exudation's own output: the final improvement is off in both runs.
Runs mesh_both(const DomainOracle& oracle, const Criteria& criteria, bool perturb = false) {
  MeshOptions off;
  off.exudation.enabled = false;
  off.improvement.enabled = false;
  MeshOptions on;
  on.improvement.enabled = false;
  on.exudation.self_check = true;
  on.exudation.perturb = perturb;
  on.exudation.perturb_bound_deg = 25;  // more moves than the default, to exercise them
  return {generate_mesh(oracle, criteria, off), generate_mesh(oracle, criteria, on)};
}

/// Everything exudation promises, for one domain. `distance_to_boundary`: the
/// distance of a point to the domain's surfaces.
void expect_exudation_keeps_the_mesh(
    const Runs& r, const DomainOracle& oracle, const Criteria& criteria,
    const std::function<double(const Point3&)>& distance_to_boundary) {
  const ExudationStats& s = r.on.exudation;
  ASSERT_TRUE(s.ran);
  std::printf(
      "exudation: min dihedral %.2f -> %.2f deg, %zu/%zu moves, %.3f s, tets < 10 deg: %zu -> "
      "%zu\n",
      s.min_dihedral_before_deg, s.min_dihedral_after_deg, s.moves_accepted, s.moves_tried,
      s.seconds, s.histogram_before[0] + s.histogram_before[1],
      s.histogram_after[0] + s.histogram_after[1]);
  EXPECT_FALSE(r.off.exudation.ran);
  EXPECT_GT(s.moves_accepted, 0u);
  EXPECT_LE(s.moves_accepted, s.moves_tried);

  // Never worse; the statistics describe the output.
  EXPECT_GE(s.min_dihedral_after_deg, s.min_dihedral_before_deg);
  EXPECT_NEAR(s.min_dihedral_before_deg, min_dihedral_deg(r.off.mesh), 1e-6);
  EXPECT_NEAR(s.min_dihedral_after_deg, min_dihedral_deg(r.on.mesh), 1e-6);
  std::size_t before = 0, after = 0;
  for (std::size_t n : s.histogram_before) before += n;
  for (std::size_t n : s.histogram_after) after += n;
  EXPECT_EQ(before, r.off.mesh.tets.size());
  EXPECT_EQ(after, r.on.mesh.tets.size());
  // No tet below 5 degrees is left on a smooth domain.
  EXPECT_EQ(s.histogram_after[0], 0u) << "min dihedral after: " << s.min_dihedral_after_deg;

  // Same vertices, same boundary (triangles with their patches), same regions.
  EXPECT_EQ(r.on.mesh.vertices.size(), r.off.mesh.vertices.size());
  EXPECT_TRUE(triangle_set(r.on.mesh) == triangle_set(r.off.mesh));
  for (const SubdomainInfo& sub : oracle.subdomains()) {
    const double v_off = test::volume(r.off.mesh, sub.id), v_on = test::volume(r.on.mesh, sub.id);
    EXPECT_NEAR(v_on, v_off, 1e-9 * v_off) << sub.name;
  }
  test::expect_positive_orientation(r.on.mesh);
  test::expect_conforming(r.on.mesh);

  // Labels: a tet's centroid lies in its subdomain, or near the boundary
  // (the polyhedral boundary is within the facet distance of the surface).
  std::size_t wrong = 0;
  for (std::size_t t = 0; t < r.on.mesh.tets.size(); ++t) {
    const auto& q = r.on.mesh.tets[t];
    const auto& v = r.on.mesh.vertices;
    const Point3 g = 0.25 * (v[q[0]] + v[q[1]] + v[q[2]] + v[q[3]]);
    if (oracle.locate(g).label != r.on.mesh.tet_subdomain[t] &&
        distance_to_boundary(g) > criteria.facet_distance.constant)
      ++wrong;
  }
  EXPECT_EQ(wrong, 0u) << "tets whose centroid is far from their subdomain";
}

TEST(Exudation, SphereKeepsItsBoundaryAndLosesItsSlivers) {
  const ImplicitOracle oracle = unit_sphere();
  const Criteria criteria = uniform_criteria(0.1);
  const Runs r = mesh_both(oracle, criteria);
  expect_exudation_keeps_the_mesh(r, oracle, criteria,
                                  [](const Point3& p) { return std::abs(norm(p) - 1.0); });
  EXPECT_EQ(euler_characteristic(r.on.mesh.triangles), 2);
}

TEST(Exudation, TorusKeepsItsBoundaryAndLosesItsSlivers) {
  const ImplicitOracle oracle({{-1.5, -1.5, -0.5}, {1.5, 1.5, 0.5}}, {torus});
  const Criteria criteria = uniform_criteria(0.1);
  const Runs r = mesh_both(oracle, criteria);
  expect_exudation_keeps_the_mesh(r, oracle, criteria, [](const Point3& p) {
    const double q = std::sqrt(p.x * p.x + p.y * p.y) - 1.0;
    return std::abs(std::sqrt(q * q + p.z * p.z) - 0.35);
  });
}

TEST(Exudation, NestedSpheresKeepTheirInterfaceAndBothLabels) {
  const ImplicitOracle oracle = nested_spheres();
  Criteria criteria = uniform_criteria(0.1);
  criteria.facet_distance = 0.003;
  const Runs r = mesh_both(oracle, criteria);
  expect_exudation_keeps_the_mesh(r, oracle, criteria, [](const Point3& p) {
    return std::min(std::abs(norm(p) - 0.5), std::abs(norm(p) - 1.0));
  });
  const std::set<int> labels([&] {
    std::set<int> l;
    for (SubdomainId s : r.on.mesh.tet_subdomain) l.insert(s.value);
    return l;
  }());
  EXPECT_EQ(labels, (std::set<int>{1, 2}));
}

TEST(Exudation, PerturbationOfWeightedVerticesKeepsTheBoundary) {
  const ImplicitOracle oracle = nested_spheres();
  Criteria criteria = uniform_criteria(0.1);
  criteria.facet_distance = 0.003;
  const Runs r = mesh_both(oracle, criteria, /*perturb=*/true);
  EXPECT_GT(r.on.exudation.perturb_moves_accepted, 0u);
  EXPECT_GE(r.on.exudation.min_dihedral_after_perturb_deg, r.on.exudation.min_dihedral_before_deg);
  EXPECT_GE(r.on.exudation.min_dihedral_after_deg, r.on.exudation.min_dihedral_after_perturb_deg);
  expect_exudation_keeps_the_mesh(r, oracle, criteria, [](const Point3& p) {
    return std::min(std::abs(norm(p) - 0.5), std::abs(norm(p) - 1.0));
  });
}

TEST(Exudation, CappedCylinderKeepsItsSharpRims) {
  const test::CappedCylinderOracle oracle(0.5, 0.5);
  Criteria criteria;
  criteria.edge_size = criteria.facet_size = criteria.cell_size = ScalarField::uniform(0.1);
  criteria.facet_distance = 0.01;
  const Runs r = mesh_both(oracle, criteria);
  const ExudationStats& s = r.on.exudation;
  std::printf(
      "exudation (capped cylinder): min dihedral %.2f -> %.2f deg, tets < 5 deg: %zu -> %zu\n",
      s.min_dihedral_before_deg, s.min_dihedral_after_deg, s.histogram_before[0],
      s.histogram_after[0]);
  EXPECT_GT(s.moves_accepted, 0u);
  EXPECT_GE(s.min_dihedral_after_deg, s.min_dihedral_before_deg);
  EXPECT_LE(s.histogram_after[0], s.histogram_before[0]);
  ASSERT_FALSE(r.off.mesh.edges.empty());
  EXPECT_TRUE(edge_set(r.on.mesh) == edge_set(r.off.mesh));
  EXPECT_TRUE(triangle_set(r.on.mesh) == triangle_set(r.off.mesh));
  EXPECT_EQ(r.on.mesh.corner_vertices.size(), r.off.mesh.corner_vertices.size());
  EXPECT_EQ(r.on.stats.unmeshed_feature_edges, 0u);
  test::expect_positive_orientation(r.on.mesh);
  test::expect_conforming(r.on.mesh);
  // Every feature edge is an edge of a tetrahedron.
  std::set<std::pair<int, int>> tet_edges;
  for (const auto& t : r.on.mesh.tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) tet_edges.insert(std::minmax(t[i], t[j]));
  for (const auto& e : r.on.mesh.edges) EXPECT_TRUE(tet_edges.count(std::minmax(e[0], e[1])));
}

TEST(Exudation, TimeLimitStopsEarlyAndLeavesAValidMesh) {
  const ImplicitOracle oracle = unit_sphere();
  MeshOptions options;
  options.exudation.time_limit_seconds = 1e-6;
  options.exudation.self_check = true;
  const MeshResult r = generate_mesh(oracle, uniform_criteria(0.15), options);
  EXPECT_TRUE(r.exudation.time_limit_reached);
  EXPECT_GE(r.exudation.min_dihedral_after_deg, r.exudation.min_dihedral_before_deg);
  test::expect_positive_orientation(r.mesh);
  test::expect_conforming(r.mesh);
}

TEST(Exudation, IsDeterministic) {
  const ImplicitOracle oracle = unit_sphere();
  const MeshResult a = generate_mesh(oracle, uniform_criteria(0.15));
  const MeshResult b = generate_mesh(oracle, uniform_criteria(0.15));
  EXPECT_EQ(a.mesh.tets, b.mesh.tets);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.exudation.moves_accepted, b.exudation.moves_accepted);
}

TEST(Exudation, InvalidOptionsAreRejected) {
  const ImplicitOracle oracle = unit_sphere();
  MeshOptions options;
  options.exudation.time_limit_seconds = -1;
  EXPECT_THROW(generate_mesh(oracle, uniform_criteria(0.3), options), InputError);
  options = {};
  options.exudation.max_weight_ratio = 1.5;
  EXPECT_THROW(generate_mesh(oracle, uniform_criteria(0.3), options), InputError);
  options = {};
  options.exudation.sliver_bound_deg = 0;
  EXPECT_THROW(generate_mesh(oracle, uniform_criteria(0.3), options), InputError);
}

}  // namespace
}  // namespace rdmesh
