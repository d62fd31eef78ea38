// Second-order meshes: the Jacobian bounds of a 10-node tetrahedron against
// closed forms, make_second_order on a meshed sphere (nodes on the sphere,
// volume error against P1, determinism), straightening of nodes that would
// invert an element, and the three writers read back by meshio and Gmsh.
#include "rdmesh/second_order.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "core/test_domains.h"
#include "io/meshio_util.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesher.h"

namespace rdmesh {
namespace {

/// The 10 nodes of the quadratic map `f` of the reference tetrahedron, Gmsh's order.
template <class F>
std::array<Point3, 10> interpolate(F f) {
  const std::array<Point3, 4> v{Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{0, 0, 1}};
  std::array<Point3, 10> x;
  for (int i = 0; i < 4; ++i) x[i] = f(v[i]);
  for (int k = 0; k < 6; ++k) x[4 + k] = f(0.5 * (v[kTetEdges[k][0]] + v[kTetEdges[k][1]]));
  return x;
}

TEST(Tet10Jacobian, StraightTetrahedronHasAConstantJacobian) {
  const auto x = interpolate([](const Point3& p) {
    return Point3{2 * p.x + 0.3 * p.y, 3 * p.y, 0.5 * p.z + 0.1 * p.x};
  });
  const JacobianBounds b = tet10_jacobian(x);
  EXPECT_NEAR(b.lower, 3.0, 1e-12);  // det of the linear map
  EXPECT_NEAR(b.upper, 3.0, 1e-12);
  EXPECT_NEAR(b.volume, 0.5, 1e-12);
  EXPECT_NEAR(b.scaled(), 1.0, 1e-12);
}

TEST(Tet10Jacobian, QuadraticMapMatchesItsClosedForm) {
  // x -> x (1 + c x): det J = 1 + 2 c x, between 1 and 1 + 2c on the
  // reference tetrahedron, integral 1/6 + c/12. Its cubic Bernstein
  // coefficients are 1 + 2c a1/3: the bounds are the exact extremes.
  for (double c : {0.4, -0.3, -0.75}) {
    const auto x = interpolate([c](const Point3& p) {
      return Point3{p.x * (1 + c * p.x), p.y, p.z};
    });
    const JacobianBounds b = tet10_jacobian(x);
    EXPECT_NEAR(b.lower, std::min(1.0, 1 + 2 * c), 1e-12) << c;
    EXPECT_NEAR(b.upper, std::max(1.0, 1 + 2 * c), 1e-12) << c;
    EXPECT_NEAR(b.volume, 1.0 / 6 + c / 12, 1e-12) << c;
  }
  // c = -0.75 folds the element (det J = -0.5 at x = 1): caught.
  const auto folded = interpolate([](const Point3& p) {
    return Point3{p.x * (1 - 0.75 * p.x), p.y, p.z};
  });
  EXPECT_LT(tet10_jacobian(folded).scaled(), 0);
}

TEST(Tet10Jacobian, BoundsEncloseSampledValues) {
  // A generic curved element: det J sampled by finite differences of the
  // quadratic map lies within the bounds.
  auto f = [](const Point3& p) {
    return Point3{p.x + 0.2 * p.y * p.z, p.y + 0.15 * p.x * p.x,
                  p.z - 0.1 * p.x * p.y + 0.05 * p.z * p.z};
  };
  const JacobianBounds b = tet10_jacobian(interpolate(f));
  for (int i = 0; i <= 6; ++i) {
    for (int j = 0; i + j <= 6; ++j) {
      for (int k = 0; i + j + k <= 6; ++k) {
        const Point3 p{i / 6.0, j / 6.0, k / 6.0};
        const double h = 1e-6;
        const Point3 dx = (1 / (2 * h)) * (f(p + Point3{h, 0, 0}) - f(p - Point3{h, 0, 0}));
        const Point3 dy = (1 / (2 * h)) * (f(p + Point3{0, h, 0}) - f(p - Point3{0, h, 0}));
        const Point3 dz = (1 / (2 * h)) * (f(p + Point3{0, 0, h}) - f(p - Point3{0, 0, h}));
        const double det = dot(dx, cross(dy, dz));
        EXPECT_GE(det, b.lower - 1e-8);
        EXPECT_LE(det, b.upper + 1e-8);
      }
    }
  }
}

class SphereP2 : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    oracle_ = new ImplicitOracle(test::unit_sphere());
    p1_ = new TetMesh(generate_mesh(*oracle_, test::uniform_criteria(0.3)).mesh);
    p2_ = new TetMesh(*p1_);
    stats_ = make_second_order(*p2_, *oracle_);
  }
  static void TearDownTestSuite() {
    delete p2_;
    delete p1_;
    delete oracle_;
  }
  static ImplicitOracle* oracle_;
  static TetMesh *p1_, *p2_;
  static SecondOrderStats stats_;
};
ImplicitOracle* SphereP2::oracle_ = nullptr;
TetMesh* SphereP2::p1_ = nullptr;
TetMesh* SphereP2::p2_ = nullptr;
SecondOrderStats SphereP2::stats_;

TEST_F(SphereP2, OneNodePerEdgeSharedByItsElements) {
  std::set<std::pair<int, int>> edges;
  for (const auto& t : p1_->tets) {
    for (const auto& [i, j] : kTetEdges) edges.insert(std::minmax(t[i], t[j]));
  }
  EXPECT_EQ(stats_.mid_nodes, edges.size());
  EXPECT_EQ(p2_->vertices.size(), p1_->vertices.size() + edges.size());
  ASSERT_EQ(p2_->tet_mid_nodes.size(), p2_->tets.size());
  ASSERT_EQ(p2_->triangle_mid_nodes.size(), p2_->triangles.size());
  std::map<std::pair<int, int>, int> node_of_edge;
  for (std::size_t t = 0; t < p2_->tets.size(); ++t) {
    for (int k = 0; k < 6; ++k) {
      const auto e = std::minmax(p2_->tets[t][kTetEdges[k][0]], p2_->tets[t][kTetEdges[k][1]]);
      const int node = p2_->tet_mid_nodes[t][k];
      EXPECT_GE(node, static_cast<int>(p1_->vertices.size()));
      EXPECT_EQ(node_of_edge.emplace(e, node).first->second, node);
    }
  }
  for (std::size_t f = 0; f < p2_->triangles.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const auto e = std::minmax(p2_->triangles[f][kTriangleEdges[k][0]],
                                 p2_->triangles[f][kTriangleEdges[k][1]]);
      EXPECT_EQ(node_of_edge.at(e), p2_->triangle_mid_nodes[f][k]);
    }
  }
}

TEST_F(SphereP2, BoundaryNodesOnTheSphereInteriorNodesAtMidpoints) {
  std::set<int> boundary;
  for (const auto& m : p2_->triangle_mid_nodes) boundary.insert(m.begin(), m.end());
  EXPECT_EQ(stats_.surface_nodes + stats_.placement_failures, boundary.size());
  EXPECT_EQ(stats_.placement_failures, 0u);
  std::size_t on_sphere = 0;
  for (int v : boundary) on_sphere += std::abs(norm(p2_->vertices[v]) - 1) <= oracle_->tolerance();
  // Only the straightened nodes may stay on their chords.
  EXPECT_GE(on_sphere + stats_.straightened, boundary.size());
  EXPECT_GE(on_sphere, boundary.size() * 95 / 100);
  for (std::size_t t = 0; t < p2_->tets.size(); ++t) {
    for (int k = 0; k < 6; ++k) {
      const int v = p2_->tet_mid_nodes[t][k];
      if (boundary.count(v)) continue;
      const Point3 mid = 0.5 * (p2_->vertices[p2_->tets[t][kTetEdges[k][0]]] +
                                p2_->vertices[p2_->tets[t][kTetEdges[k][1]]]);
      EXPECT_EQ(p2_->vertices[v], mid);
    }
  }
}

TEST_F(SphereP2, AllJacobiansPositiveAndVolumeErrorFarBelowP1) {
  double min_scaled = 1;
  for (std::size_t t = 0; t < p2_->tets.size(); ++t) {
    const JacobianBounds b = tet10_jacobian(tet10_nodes(*p2_, t));
    ASSERT_GT(b.lower, 0) << "tet " << t;
    min_scaled = std::min(min_scaled, b.scaled());
  }
  EXPECT_NEAR(min_scaled, stats_.min_scaled_jacobian, 1e-12);
  EXPECT_GT(stats_.min_scaled_jacobian, SecondOrderOptions{}.min_scaled_jacobian);
  const double exact = 4.0 / 3.0 * std::numbers::pi;
  const double e1 = std::abs(mesh_volume(*p1_) - exact) / exact;
  const double e2 = std::abs(mesh_volume(*p2_) - exact) / exact;
  std::printf(
      "sphere h=0.3: %zu tets, P1 volume error %.3g, P2 %.3g (%.0fx smaller), %zu of %zu "
      "surface nodes straightened, min scaled Jacobian %.3f\n",
      p1_->tets.size(), e1, e2, e1 / e2, stats_.straightened, stats_.surface_nodes,
      stats_.min_scaled_jacobian);
  EXPECT_LT(e2, e1 / 20);
}

TEST_F(SphereP2, SameInputSameNodes) {
  TetMesh again(*p1_);
  make_second_order(again, *oracle_);
  EXPECT_EQ(again.vertices, p2_->vertices);
  EXPECT_EQ(again.tet_mid_nodes, p2_->tet_mid_nodes);
  EXPECT_THROW(make_second_order(again, *oracle_), InputError);  // already second order
}

/// One flat tetrahedron whose bottom face is patch 1; project() moves a
/// point by `lift` along z (a fake surface that bulges into the element).
class LiftingOracle : public DomainOracle {
 public:
  explicit LiftingOracle(double lift) : lift_(lift) {}
  Box3 bounding_box() const override { return {{-1, -1, -1}, {2, 2, 2}}; }
  Located locate(const Point3&, const std::optional<LocateHint>& = std::nullopt) const override {
    return {SubdomainId(1)};
  }
  std::optional<SurfaceHit> intersect(const Point3&, const Point3&) const override {
    return std::nullopt;
  }
  std::vector<SubdomainInfo> subdomains() const override { return {{SubdomainId(1), "s"}}; }
  std::vector<PatchInfo> patches() const override {
    return {{PatchId(1), "p", kOutside, SubdomainId(1)}};
  }
  std::vector<Point3> initial_points(PatchId) const override { return {}; }
  std::optional<Point3> project(const Point3& p, PatchId) const override {
    return p + Point3{0, 0, lift_};
  }
  double tolerance() const override { return 1e-12; }

 private:
  double lift_;
};

TetMesh flat_tet() {
  TetMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0.05}};
  m.tets = {{0, 1, 2, 3}};
  m.tet_subdomain = {SubdomainId(1)};
  m.triangles = {{0, 2, 1}};
  m.triangle_patch = {PatchId(1)};
  return m;
}

TEST(SecondOrder, NodesThatWouldInvertAnElementAreStraightened) {
  // Lifting the bottom face's three mid nodes above the apex folds the element.
  TetMesh m = flat_tet();
  std::array<Point3, 10> lifted;
  for (int i = 0; i < 4; ++i) lifted[i] = m.vertices[i];
  for (int k = 0; k < 6; ++k) {
    const auto [i, j] = kTetEdges[k];
    lifted[4 + k] =
        0.5 * (m.vertices[i] + m.vertices[j]) + Point3{0, 0, i != 3 && j != 3 ? 0.2 : 0};
  }
  ASSERT_LT(tet10_jacobian(lifted).lower, 0);
  const SecondOrderStats s = make_second_order(m, LiftingOracle(0.2));
  EXPECT_EQ(s.surface_nodes, 3u);
  EXPECT_GE(s.straightened, 1u);
  EXPECT_LE(s.straightened, 3u);
  const JacobianBounds b = tet10_jacobian(tet10_nodes(m, 0));
  EXPECT_GT(b.scaled(), SecondOrderOptions{}.min_scaled_jacobian);
  EXPECT_EQ(s.min_scaled_jacobian, b.scaled());
  std::size_t on_chord = 0;
  for (int k = 0; k < 6; ++k) {
    const Point3 mid =
        0.5 * (m.vertices[m.tets[0][kTetEdges[k][0]]] + m.vertices[m.tets[0][kTetEdges[k][1]]]);
    on_chord += m.vertices[m.tet_mid_nodes[0][k]] == mid;
  }
  EXPECT_EQ(on_chord, 3 + s.straightened);  // the three edges to the apex, and those straightened
  // Bulging outwards keeps them curved.
  TetMesh out = flat_tet();
  const SecondOrderStats s2 = make_second_order(out, LiftingOracle(-0.01));
  EXPECT_EQ(s2.straightened, 0u);
  EXPECT_GT(s2.min_scaled_jacobian, 0);
  EXPECT_NEAR(s2.max_relative_offset, 0.01, 1e-12);  // on the unit edges 01 and 02
  EXPECT_GT(mesh_volume(out), 0.05 / 6);
}

TEST(SecondOrder, RefusesBadOptions) {
  TetMesh m = flat_tet();
  EXPECT_THROW(make_second_order(m, LiftingOracle(0), {1.0}), InputError);
  EXPECT_THROW(make_second_order(m, LiftingOracle(0), {-0.1}), InputError);
  EXPECT_FALSE(is_second_order(m));
}

class SecondOrderFiles : public testing::MeshioTest {};

TEST_F(SecondOrderFiles, MeshioReadsQuadraticCellsInVtkOrder) {
  const ImplicitOracle sphere = test::unit_sphere();
  TetMesh mesh = generate_mesh(sphere, test::uniform_criteria(0.5)).mesh;
  make_second_order(mesh, sphere);
  // meshio turns Gmsh's tetra10 order into its own (VTK's): both files must
  // give the same cells, ours with the last two mid nodes swapped.
  for (const char* name : {"p2.msh", "p2.vtu"}) {
    const nlohmann::json j = write_and_read(mesh, name);
    ASSERT_EQ(j["points"].size(), mesh.vertices.size()) << name;
    std::map<std::string, std::size_t> count;
    for (const auto& block : j["cells"]) {
      count[block["type"]] += block["data"].size();
      if (block["type"] != "tetra10") continue;
      // Blocks come in tet order (one subdomain here).
      for (std::size_t t = 0; t < block["data"].size(); ++t) {
        const auto& c = block["data"][t];
        const auto& v = mesh.tets[t];
        const auto& m = mesh.tet_mid_nodes[t];
        const std::array<int, 10> expected{v[0], v[1], v[2], v[3], m[0],
                                           m[1], m[2], m[3], m[5], m[4]};
        for (int i = 0; i < 10; ++i)
          ASSERT_EQ(c[i].get<int>(), expected[i]) << name << " tet " << t;
      }
    }
    EXPECT_EQ(count["tetra10"], mesh.tets.size()) << name;
    EXPECT_EQ(count["triangle6"], mesh.triangles.size()) << name;
    EXPECT_EQ(count.count("tetra"), 0u) << name;
  }
}

TEST_F(SecondOrderFiles, GmshReadsTheMshAndMeditWritesP2Sections) {
  const ImplicitOracle sphere = test::unit_sphere();
  TetMesh mesh = generate_mesh(sphere, test::uniform_criteria(0.5)).mesh;
  make_second_order(mesh, sphere);
  write_mesh(mesh, dir_.file("p2.mesh"));
  const std::string medit = testing::read_text(dir_.file("p2.mesh"));
  EXPECT_NE(medit.find("\nTetrahedraP2\n" + std::to_string(mesh.tets.size()) + "\n"),
            std::string::npos);
  EXPECT_NE(medit.find("\nTrianglesP2\n" + std::to_string(mesh.triangles.size()) + "\n"),
            std::string::npos);
  EXPECT_EQ(medit.find("\nTetrahedra\n"), std::string::npos);
  if (!testing::gmsh_available()) RDMESH_MISSING_PREREQUISITE("gmsh");
  // Gmsh's own Jacobian analysis of the .msh: positive everywhere, and its
  // worst min J / max J is our certified bound (its Bezier bounds are at
  // least as tight).
  write_mesh(mesh, dir_.file("p2.msh"));
  testing::write_text(dir_.file("q.geo"),
                      "Merge \"" + dir_.file("p2.msh") +
                          "\";\nPlugin(AnalyseMeshQuality).JacobianDeterminant = 1;\n"
                          "Plugin(AnalyseMeshQuality).DimensionOfElements = 3;\n"
                          "Plugin(AnalyseMeshQuality).Run;\n");
  const std::string log = testing::expect_gmsh_accepts("-0 " + dir_.file("q.geo"));
  double min_j = 0, avg_j = 0, max_j = 0, worst = 0;
  const auto at = log.find("minJ      =");
  ASSERT_NE(at, std::string::npos) << log;
  ASSERT_EQ(std::sscanf(log.c_str() + at, "minJ      = %lf, %lf, %lf", &min_j, &avg_j, &max_j), 3);
  const auto ratio = log.find("minJ/maxJ =", log.find("(avg on the"));
  ASSERT_NE(ratio, std::string::npos) << log;
  ASSERT_EQ(std::sscanf(log.c_str() + ratio, "minJ/maxJ = %lf", &worst), 1);
  EXPECT_GT(min_j, 0);
  double ours = 1;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    ours = std::min(ours, tet10_jacobian(tet10_nodes(mesh, t)).scaled());
  }
  EXPECT_GE(worst, ours - 1e-3);
  EXPECT_LE(worst, ours + 0.05);
}

}  // namespace
}  // namespace rdmesh
