// The feature table the built-in oracles share: ids 1..n, one unknown-id
// error, initial points by patch id.
#include "rdmesh/feature_table.h"

#include <gtest/gtest.h>

#include <string>

#include "oracles/error_of.h"
#include "rdmesh/errors.h"
#include "rdmesh/implicit_oracle.h"
#include "rdmesh/polyline_curve.h"
#include "rdmesh/triangle_mesh_oracle.h"

namespace rdmesh {
namespace {

TEST(FeatureTable, NumbersFeaturesFromOneAndRefusesOtherIds) {
  FeatureTable<PolylineCurve> t;
  EXPECT_EQ(t.add_corner({0, 0, 0}).id, CornerId(1));
  EXPECT_EQ(t.add_corner({1, 0, 0}).id, CornerId(2));
  EXPECT_EQ(t.corner(CornerId(2)).point, (Point3{1, 0, 0}));
  EXPECT_EQ(t.next_curve_id(), CurveId(1));
  CurveInfo info;
  info.name = "segment";
  const CurveInfo& added =
      t.add_curve(info, std::make_unique<PolylineCurve>(std::vector<Point3>{{0, 0, 0}, {1, 0, 0}}));
  EXPECT_EQ(added.id, CurveId(1));
  EXPECT_EQ(t.curves().size(), 1u);
  EXPECT_EQ(t.curve(CurveId(1)).point(t.curve(CurveId(1)).t_end()), (Point3{1, 0, 0}));
  EXPECT_EQ(error_of<OracleError>([&] { t.curve(CurveId(2)); }), "no curve 2 (ids 1..1)");
  EXPECT_EQ(error_of<OracleError>([&] { t.curve(CurveId(-1)); }), "no curve -1 (ids 1..1)");
  EXPECT_EQ(error_of<OracleError>([&] { t.corner(CornerId(3)); }), "no corner 3 (ids 1..2)");
}

TEST(FeatureTable, KeepsInitialPointsByPatchId) {
  FeatureTable<> t;
  t.set_patch_count(2);
  t.add_initial_points(PatchId(2), {{0, 0, 1}});
  t.add_initial_points(PatchId(2), {{0, 0, 2}, {0, 0, 3}});
  EXPECT_TRUE(t.initial_points(PatchId(1)).empty());
  ASSERT_EQ(t.initial_points(PatchId(2)).size(), 3u);
  EXPECT_EQ(t.initial_points(PatchId(2))[2], (Point3{0, 0, 3}));
  EXPECT_TRUE(t.initial_points(PatchId(0)).empty());
  EXPECT_TRUE(t.initial_points(PatchId(3)).empty());
  EXPECT_EQ(t.initial_point_count(), 3u);
  EXPECT_EQ(error_of<OracleError>([&] { t.add_initial_points(PatchId(3), {}); }),
            "no patch 3 (ids 1..2)");
}

// The built-in oracles answer through the table: one message for an unknown curve.
TEST(FeatureTable, TheBuiltInOraclesShareTheUnknownCurveError) {
  const ImplicitOracle sphere({{-2, -2, -2}, {2, 2, 2}},
                              {[](const Point3& p) { return squared_norm(p) - 1; }});
  EXPECT_EQ(error_of<OracleError>([&] { sphere.curve(CurveId(1)); }),
            "no curve 1 (there are none)");
  EXPECT_EQ(sphere.initial_points(PatchId(1)).size() >= 3, true);

  TriangleSoup cube;
  for (int i = 0; i < 8; ++i)
    cube.points.push_back({double(i & 1), double(i >> 1 & 1), double(i >> 2)});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    cube.triangles.push_back({q[0], q[1], q[2]});
    cube.triangles.push_back({q[0], q[2], q[3]});
  }
  const TriangleMeshOracle mesh(cube, "cube");
  const std::size_t n = mesh.curves().size();
  EXPECT_EQ(n, 12u);  // the cube's edges
  EXPECT_EQ(error_of<OracleError>([&] { mesh.curve(CurveId(13)); }), "no curve 13 (ids 1..12)");
  for (const PatchInfo& p : mesh.patches()) EXPECT_GE(mesh.initial_points(p.id).size(), 3u);
}

}  // namespace
}  // namespace rdmesh
