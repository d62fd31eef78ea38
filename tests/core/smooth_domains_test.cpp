// End-to-end refinement of smooth implicit domains, checked against the
// output properties of RR-7912 section 4: topology of the restricted surface
// (Euler characteristic), Hausdorff distance, volume, labels, conformity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

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

using test::connected_components;
using test::patch_triangles;

/// Refinement's own output: labels at circumcenters and R5.1 are properties of
/// D|O before sliver exudation and the final improvement, which change tets
/// (see exudation_test.cpp and tet_improvement_test.cpp).
MeshOptions refinement_only() {
  MeshOptions o;
  o.exudation.enabled = false;
  o.improvement.enabled = false;
  return o;
}

void expect_valid_mesh(const TetMesh& mesh, const DomainOracle& oracle) {
  ASSERT_GT(mesh.tets.size(), 100u);
  test::expect_positive_orientation(mesh);
  test::expect_conforming(mesh);
  test::expect_labels_match_oracle(mesh, oracle);
}

TEST(SmoothDomains, UnitSphereIsAClosedSurfaceOfTheRightVolume) {
  const ImplicitOracle sphere = unit_sphere();
  const Criteria criteria = uniform_criteria(0.08);
  const MeshResult result = generate_mesh(sphere, criteria, refinement_only());
  const TetMesh& mesh = result.mesh;
  expect_valid_mesh(mesh, sphere);
  EXPECT_FALSE(result.stats.guard_fired());

  EXPECT_EQ(euler_characteristic(mesh.triangles), 2);
  EXPECT_TRUE(is_edge_manifold(mesh.triangles));
  EXPECT_NEAR(test::volume(mesh), 4.0 * M_PI / 3.0, 0.01 * 4.0 * M_PI / 3.0);

  // Boundary vertices on the sphere (oracle accuracy); centroids within the facet distance.
  for (const auto& t : mesh.triangles) {
    for (int i : t) EXPECT_NEAR(norm(mesh.vertices[i]), 1.0, 1e-8);
    const Point3 g =
        (1.0 / 3.0) * (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]);
    EXPECT_LE(1.0 - norm(g), criteria.facet_distance.constant);
  }
  // Size criterion R5.1 holds for every cell: circumradius <= h (checked via edges <= 2h).
  for (const auto& t : mesh.tets) {
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        EXPECT_LE(distance(mesh.vertices[t[i]], mesh.vertices[t[j]]), 2 * 0.08 + 1e-12);
  }
}

TEST(SmoothDomains, TorusHasEulerCharacteristicZero) {
  const ImplicitOracle oracle({{-1.5, -1.5, -0.5}, {1.5, 1.5, 0.5}}, {torus});
  const MeshResult result = generate_mesh(oracle, uniform_criteria(0.1), refinement_only());
  expect_valid_mesh(result.mesh, oracle);
  EXPECT_EQ(euler_characteristic(result.mesh.triangles), 0);
  EXPECT_EQ(connected_components(result.mesh.triangles), 1);
  const double exact = 2 * M_PI * M_PI * 1.0 * 0.35 * 0.35;
  EXPECT_NEAR(test::volume(result.mesh), exact, 0.02 * exact);
}

TEST(SmoothDomains, NestedSpheresShareTheirInterface) {
  // Subdomain 1: inner ball (r = 0.5); subdomain 2: the shell between r = 0.5 and r = 1.
  const ImplicitOracle oracle = nested_spheres();
  Criteria criteria = uniform_criteria(0.1);
  criteria.facet_distance = 0.003;  // the inner sphere is small: keep the volume error < 2%
  const MeshResult result = generate_mesh(oracle, criteria, refinement_only());
  const TetMesh& mesh = result.mesh;
  expect_valid_mesh(mesh, oracle);
  ASSERT_EQ(oracle.subdomains().size(), 2u);
  ASSERT_EQ(oracle.patches().size(), 2u);
  EXPECT_NEAR(test::volume(mesh, SubdomainId{1}), 4.0 * M_PI / 3.0 * 0.125, 0.02 * 0.5236);
  EXPECT_NEAR(test::volume(mesh, SubdomainId{2}), 4.0 * M_PI / 3.0 * 0.875, 0.02 * 3.665);
  for (const PatchInfo& patch : oracle.patches()) {
    const auto tris = patch_triangles(mesh, patch.id);
    EXPECT_EQ(euler_characteristic(tris), 2) << patch.name;
    EXPECT_EQ(connected_components(tris), 1) << patch.name;
  }
  // The interface (core|shell) is a face of tets of both labels.
  const PatchId interface = oracle.patch_between(SubdomainId{1}, SubdomainId{2});
  std::set<std::array<int, 3>> iface;
  for (auto t : patch_triangles(mesh, interface)) {
    std::sort(t.begin(), t.end());
    iface.insert(t);
  }
  ASSERT_FALSE(iface.empty());
  std::set<int> labels_touching;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& q = mesh.tets[t];
    for (int i = 0; i < 4; ++i) {
      std::array<int, 3> f{q[(i + 1) % 4], q[(i + 2) % 4], q[(i + 3) % 4]};
      std::sort(f.begin(), f.end());
      if (iface.count(f)) labels_touching.insert(mesh.tet_subdomain[t].value);
    }
  }
  EXPECT_EQ(labels_touching, (std::set<int>{1, 2}));
}

TEST(SmoothDomains, DisjointBallsAreAllFound) {
  auto ball = [](Point3 c, double r) {
    return [c, r](const Point3& p) { return squared_norm(p - c) - r * r; };
  };
  auto b1 = ball({-1, 0, 0}, 0.4), b2 = ball({0.2, 0, 0}, 0.3), b3 = ball({1, 0.6, 0}, 0.25);
  const ImplicitOracle oracle({{-1.5, -1, -1}, {1.5, 1, 1}}, {[=](const Point3& p) {
                                return std::min({b1(p), b2(p), b3(p)});
                              }});
  Criteria criteria = uniform_criteria(0.06);
  criteria.facet_distance = 0.002;
  const MeshResult result = generate_mesh(oracle, criteria, refinement_only());
  expect_valid_mesh(result.mesh, oracle);
  EXPECT_EQ(connected_components(result.mesh.triangles), 3);
  EXPECT_EQ(euler_characteristic(result.mesh.triangles), 6);
  const double exact = 4.0 * M_PI / 3.0 * (0.064 + 0.027 + 0.015625);
  EXPECT_NEAR(test::volume(result.mesh), exact, 0.02 * exact);
}

TEST(SmoothDomains, GradedSizingRefinesWhereAsked) {
  const ImplicitOracle sphere = unit_sphere();
  Criteria c = uniform_criteria(0.2);
  // Fine near x = 1, coarse near x = -1.
  c.cell_size.field = [](const Point3& p) { return 0.05 + 0.1 * (1.0 - p.x); };
  c.facet_size = c.cell_size;
  c.facet_distance = 0.005;
  const TetMesh mesh = generate_mesh(sphere, c, refinement_only()).mesh;
  expect_valid_mesh(mesh, sphere);
  std::size_t near_fine = 0, near_coarse = 0;
  for (const Point3& v : mesh.vertices) {
    near_fine += v.x > 0.5;
    near_coarse += v.x < -0.5;
  }
  EXPECT_GT(near_fine, 3 * near_coarse);
}

TEST(SmoothDomains, RefinementIsDeterministic) {
  const ImplicitOracle sphere = unit_sphere();
  const TetMesh a = generate_mesh(sphere, uniform_criteria(0.15)).mesh;
  const TetMesh b = generate_mesh(sphere, uniform_criteria(0.15)).mesh;
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.tets, b.tets);
  EXPECT_EQ(a.triangles, b.triangles);
}

TEST(SmoothDomains, InvalidCriteriaAreRejected) {
  const ImplicitOracle sphere = unit_sphere();
  Criteria c = uniform_criteria(0.1);
  c.facet_distance = -1;
  EXPECT_THROW(generate_mesh(sphere, c), InputError);
  c = uniform_criteria(std::nan(""));
  EXPECT_THROW(generate_mesh(sphere, c), InputError);
}

}  // namespace
}  // namespace rdmesh

namespace rdmesh {
namespace {

/// An oracle whose initial points all sit on one side of a thin slab: no
/// Voronoi vertex falls inside, so refinement has nothing to start from.
class BlindOracle final : public DomainOracle {
 public:
  Box3 bounding_box() const override { return {{-1, -1, -1}, {1, 1, 1}}; }
  Located locate(const Point3& p, const std::optional<LocateHint>& = std::nullopt) const override {
    return {std::abs(p.z) < 1e-3 && bounding_box().contains(p) ? SubdomainId{1} : kOutside};
  }
  std::optional<SurfaceHit> intersect(const Point3&, const Point3&) const override {
    return std::nullopt;
  }
  std::vector<SubdomainInfo> subdomains() const override { return {{SubdomainId{1}, "slab"}}; }
  std::vector<PatchInfo> patches() const override {
    return {{PatchId{1}, "slab", kOutside, SubdomainId{1}}};
  }
  std::vector<Point3> initial_points(PatchId) const override {
    return {{0, 0, 0.9}, {1, 0, 0.95}, {0, 1, 0.9}, {0.5, 0.5, 0.5}, {-0.5, 0.2, 0.7}};
  }
  std::optional<Point3> project(const Point3& p, PatchId) const override { return p; }
  double tolerance() const override { return 1e-12; }
};

TEST(SmoothDomains, AnEmptyResultIsAnErrorNotASilentEmptyMesh) {
  const BlindOracle oracle;
  Criteria c;
  c.facet_size = c.cell_size = ScalarField::uniform(0.5);
  c.facet_distance = 0.05;
  // The criteria are too coarse for this 2e-3 slab: an input error, not an
  // internal one (exit 2 on the command line, not 3).
  try {
    generate_mesh(oracle, c);
    ADD_FAILURE() << "an empty mesh was returned";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no tetrahedron has its centre inside the domain"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rdmesh
