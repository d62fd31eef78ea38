// Second-order meshes of shared STEP parts: mid nodes of feature edges on
// their B-rep edge curves, mid nodes of boundary triangles on their faces,
// every Jacobian positive, and the volume error against OpenCASCADE's exact
// volume far below the first-order mesh's at the same vertices.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

#include "rdmesh/cad_oracle.h"
#include "rdmesh/mesher.h"
#include "rdmesh/second_order.h"
#include "shared_data.h"

namespace rdmesh {
namespace {

struct Part {
  const char* file;
  double size;      ///< fraction of the bounding box's diagonal
  double min_gain;  ///< P1 volume error / P2 volume error at least this
};

class SecondOrderCad : public ::testing::TestWithParam<Part> {};

TEST_P(SecondOrderCad, NodesOnTheBRepJacobiansPositiveVolumeCloser) {
  const Part& part = GetParam();
  const std::string path = test::shared_data(std::string("step/") + part.file);
  if (path.empty()) RDMESH_MISSING_SHARED_DATA(std::string("step/") + part.file);
  const auto oracle = load_cad_file(path);
  Criteria criteria = default_criteria(oracle->bounding_box());
  const double h = part.size * oracle->bounding_box().diagonal();
  criteria.edge_size = criteria.facet_size = criteria.cell_size = ScalarField::uniform(h);
  criteria.facet_distance = h / 10;
  const TetMesh p1 = generate_mesh(*oracle, criteria).mesh;
  TetMesh p2 = p1;
  const SecondOrderStats s = make_second_order(p2, *oracle);
  const double diag = oracle->bounding_box().diagonal();
  const double tol = std::max(oracle->tolerance(), 1e-9 * diag);

  // Feature edges: mid node on its curve, unless straightened.
  std::set<int> curve_nodes;
  std::size_t off_curve = 0;
  for (std::size_t e = 0; e < p2.edges.size(); ++e) {
    const int v = p2.edge_mid_nodes[e];
    curve_nodes.insert(v);
    const CurveId id = p2.edge_curve[e];
    const CurveInfo info = oracle->curves()[id.value - 1];  // curves() returns a copy
    const Curve& c = oracle->curve(id);
    const Point3 q = c.point(c.closest(p2.vertices[v], info.t_begin, info.t_end));
    off_curve += distance(q, p2.vertices[v]) > tol;
  }
  // Other boundary triangle edges: mid node on its face.
  std::set<int> face_nodes;
  std::size_t off_face = 0;
  for (std::size_t f = 0; f < p2.triangles.size(); ++f) {
    for (int v : p2.triangle_mid_nodes[f]) {
      if (curve_nodes.count(v) || !face_nodes.insert(v).second) continue;
      const std::optional<Point3> q = oracle->project(p2.vertices[v], p2.triangle_patch[f]);
      off_face += !q || distance(*q, p2.vertices[v]) > tol;
    }
  }
  EXPECT_EQ(s.curve_nodes + s.surface_nodes + s.placement_failures,
            curve_nodes.size() + face_nodes.size());
  EXPECT_LE(off_curve + off_face, s.straightened + s.placement_failures);
  EXPECT_LE(s.placement_failures, (curve_nodes.size() + face_nodes.size()) / 100);
  EXPECT_LE(s.straightened, (curve_nodes.size() + face_nodes.size()) / 20);

  for (std::size_t t = 0; t < p2.tets.size(); ++t) {
    ASSERT_GT(tet10_jacobian(tet10_nodes(p2, t)).lower, 0) << "tet " << t;
  }
  EXPECT_GT(s.min_scaled_jacobian, 0);

  const double exact = oracle->exact_volume();
  const double e1 = std::abs(mesh_volume(p1) - exact) / exact;
  const double e2 = std::abs(mesh_volume(p2) - exact) / exact;
  std::printf(
      "%s: %zu tets, volume error P1 %.3g, P2 %.3g (%.0fx smaller); %zu curve and %zu "
      "face nodes, %zu straightened, %zu failures, %zu off; min scaled Jacobian %.3f; "
      "%.3f s\n",
      part.file, p1.tets.size(), e1, e2, e1 / e2, curve_nodes.size(), face_nodes.size(),
      s.straightened, s.placement_failures, off_curve + off_face, s.min_scaled_jacobian, s.seconds);
  EXPECT_LT(e2 * part.min_gain, e1);
}

// A torus, a cube beside a cylinder (two solids, an interface), a screw
// (tori, cones, a helix-free thread), a cast housing (B-splines, fillets).
INSTANTIATE_TEST_SUITE_P(Parts, SecondOrderCad,
                         ::testing::Values(Part{"gmsh_torus_step_header_data.stp", 0.025, 20},
                                           Part{"cadquery_red_cube_blue_cylinder.step", 0.05, 20},
                                           Part{"occt_screw.step", 0.025, 20},
                                           Part{"occtsample_MBBGehauseRohteil.step", 0.05, 20}),
                         [](const auto& info) { return test::file_test_name(info.param.file); });

}  // namespace
}  // namespace rdmesh
