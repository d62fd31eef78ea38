// Tests of TriangleMeshOracle: subdomains from nested components, patches and
// sharp features, and the shared oracle conformance suite on real meshes.
#include "rdmesh/triangle_mesh_oracle.h"

#include <gtest/gtest.h>

#include <sstream>

#include "oracles/oracle_conformance.h"
#include "rdmesh/errors.h"
#include "rdmesh/polyline_curve.h"
#include "shared_data.h"

namespace rdmesh {
namespace {

/// An axis-aligned box as 12 outward triangles.
TriangleSoup box_soup(Point3 lo, Point3 hi) {
  TriangleSoup s;
  for (int i = 0; i < 8; ++i) {
    s.points.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  }
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    s.triangles.push_back({q[0], q[1], q[2]});
    s.triangles.push_back({q[0], q[2], q[3]});
  }
  return s;
}

TriangleSoup join(TriangleSoup a, const TriangleSoup& b) {
  const int offset = static_cast<int>(a.points.size());
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for (auto t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return a;
}

TEST(TriangleMeshOracle, SurfaceOnlyAcceptsAnOpenBoxAndItsBorderIsACurve) {
  // A box without its top (two triangles of the +z face removed): open.
  TriangleSoup open = box_soup({0, 0, 0}, {1, 1, 1});
  open.triangles.erase(open.triangles.begin() + 2, open.triangles.begin() + 4);
  EXPECT_THROW(TriangleMeshOracle(open, "open"), InputError);
  const TriangleMeshOracle o(open, "open", {.surface_only = true});
  EXPECT_TRUE(o.subdomains().empty());
  EXPECT_EQ(o.locate({0.5, 0.5, 0.5}).label, kOutside);
  EXPECT_EQ(o.patches().size(), 5u);
  for (const PatchInfo& p : o.patches()) {
    EXPECT_EQ(p.side_a, kOutside);
    EXPECT_EQ(p.side_b, kOutside);
  }
  // The 8 crease edges of the remaining faces plus the 4 border edges: the
  // border's corners are kinks (90 degrees), so 12 curves between 8 corners.
  EXPECT_EQ(o.sharp_edge_count(), 12);
  EXPECT_EQ(o.curves().size(), 12u);
  EXPECT_EQ(o.corners().size(), 8u);
  std::size_t border_curves = 0;
  for (const CurveInfo& c : o.curves()) border_curves += c.patches.size() == 1 ? 1 : 0;
  EXPECT_EQ(border_curves, 4u) << "each border edge bounds one patch";
  // Any segment through a wall crosses it, whatever the (absent) labels say.
  const auto hit = o.intersect({0.5, 0.5, 0.5}, {0.5, 0.5, -1});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->point.z, 0.0, 1e-12);
  EXPECT_FALSE(o.intersect({0.5, 0.5, 0.5}, {0.5, 0.5, 2}).has_value()) << "through the open top";
}

TEST(TriangleMeshOracle, CubeFeatures) {
  const TriangleMeshOracle o(box_soup({0, 0, 0}, {1, 1, 1}), "cube");
  EXPECT_EQ(o.subdomains().size(), 1u);
  EXPECT_EQ(o.patches().size(), 6u);
  EXPECT_EQ(o.sharp_edge_count(), 12);
  ASSERT_EQ(o.corners().size(), 8u);
  ASSERT_EQ(o.curves().size(), 12u);
  for (const CornerInfo& c : o.corners()) {
    EXPECT_EQ(c.curves.size(), 3u);
    EXPECT_EQ(c.patches.size(), 3u);
  }
  for (const CurveInfo& c : o.curves()) {
    EXPECT_FALSE(c.closed);
    EXPECT_EQ(c.patches.size(), 2u);
    EXPECT_NEAR(o.curve(c.id).length(c.t_begin, c.t_end), 1.0, 1e-15);
  }
  EXPECT_NEAR(o.volume(), 1.0, 1e-14);
  EXPECT_EQ(o.locate({0.5, 0.5, 0.5}).label, SubdomainId(1));
  EXPECT_EQ(o.locate({1.5, 0.5, 0.5}).label, kOutside);
  EXPECT_EQ(o.locate({0.5, 0.5, 1.0 + 1e-12}).label, kOutside);
  EXPECT_EQ(o.locate({0.5, 0.5, 1.0 - 1e-12}).label, SubdomainId(1));
  // Through the middle of an edge and a corner of the cube: rays are retried.
  EXPECT_EQ(o.locate({0.5, 0.5, 0.5}).label, SubdomainId(1));
  const auto hit = o.intersect({0.5, 0.5, 0.5}, {0.5, 0.5, 3});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.z, 1.0, 1e-15);
  EXPECT_THROW(o.curve(CurveId(13)), OracleError);
  expect_oracle_conformance(o);
}

TEST(TriangleMeshOracle, FeatureAngleAboveNinetyHasNoCurves) {
  const TriangleMeshOracle o(box_soup({0, 0, 0}, {1, 1, 1}), "cube", {.feature_angle_degrees = 95});
  EXPECT_EQ(o.patches().size(), 1u);
  EXPECT_TRUE(o.curves().empty());
  EXPECT_TRUE(o.corners().empty());
  expect_oracle_conformance(o, 500);
}

TEST(TriangleMeshOracle, NestedAndSideBySideComponents) {
  // Outer box with a box inside (a shell and a core), and a box beside them.
  TriangleSoup s = join(box_soup({0, 0, 0}, {4, 4, 4}), box_soup({1, 1, 1}, {2, 2, 2}));
  s = join(s, box_soup({5, 0, 0}, {6, 1, 1}));
  const TriangleMeshOracle o(s, "nested");
  ASSERT_EQ(o.subdomains().size(), 3u);
  EXPECT_EQ(o.locate({0.5, 0.5, 0.5}).label, SubdomainId(1));
  EXPECT_EQ(o.locate({1.5, 1.5, 1.5}).label, SubdomainId(2));
  EXPECT_EQ(o.locate({5.5, 0.5, 0.5}).label, SubdomainId(3));
  EXPECT_EQ(o.locate({4.5, 0.5, 0.5}).label, kOutside);
  EXPECT_NEAR(o.volume(), 64 + 1, 1e-12);
  ASSERT_EQ(o.patches().size(), 18u);
  for (const PatchInfo& p : o.patches()) {
    const int group = (p.id.value - 1) / 6;
    EXPECT_EQ(p.side_a.value, group == 1 ? 1 : 0) << p.name;
    EXPECT_EQ(p.side_b.value, group + 1) << p.name;
  }
  const auto hit = o.intersect({1.5, 1.5, 1.5}, {3, 1.5, 1.5});
  ASSERT_TRUE(hit);
  EXPECT_EQ(o.patches()[hit->patch.value - 1].side_b, SubdomainId(2));
  expect_oracle_conformance(o);
}

TEST(TriangleMeshOracle, OpenOrSelfIntersectingInputsAreRejected) {
  TriangleSoup open = box_soup({0, 0, 0}, {1, 1, 1});
  open.triangles.pop_back();
  EXPECT_THROW(TriangleMeshOracle(open, "open"), InputError);
  const TriangleSoup crossing =
      join(box_soup({0, 0, 0}, {2, 2, 2}), box_soup({1, 1, 1}, {3, 3, 3}));
  EXPECT_THROW(TriangleMeshOracle(crossing, "crossing"), InputError);
  EXPECT_THROW(
      TriangleMeshOracle(box_soup({0, 0, 0}, {1, 1, 1}), "x", {.feature_angle_degrees = -1}),
      InputError);
}

TEST(TriangleMeshOracle, Fandisk) {
  RDMESH_REQUIRE_SHARED_DATA(path, "mesh/cgal_fandisk.off");
  const auto o = TriangleMeshOracle::from_file(path);
  EXPECT_EQ(o->subdomains().size(), 1u);
  EXPECT_GT(o->patches().size(), 10u);
  EXPECT_GT(o->curves().size(), 10u);
  EXPECT_GT(o->corners().size(), 4u);
  // Every curve's ends are corners, and corners list curves that end there.
  for (const CurveInfo& c : o->curves()) {
    if (c.closed) continue;
    const Curve& curve = o->curve(c.id);
    EXPECT_EQ(curve.point(c.t_begin), o->corners()[c.start.value - 1].point);
    EXPECT_EQ(curve.point(c.t_end), o->corners()[c.end.value - 1].point);
  }
  // Curves are smooth: no polyline vertex inside a curve turns by more than
  // the feature angle (60 degrees); such kinks are corners.
  for (const CurveInfo& c : o->curves()) {
    const auto* polyline = dynamic_cast<const PolylineCurve*>(&o->curve(c.id));
    ASSERT_NE(polyline, nullptr);
    const std::vector<Point3>& p = polyline->points();
    const std::size_t n = p.size();
    for (std::size_t k = c.closed ? 0 : 1; k + (c.closed ? 0 : 1) < n; ++k) {
      const Point3 prev = p[(k + n - 1 - (c.closed ? 1 : 0)) % n], next = p[(k + 1) % n];
      const Point3 in = p[k] - prev, out = next - p[k];
      if (c.closed && k + 1 == n) break;  // the repeated first point
      EXPECT_GE(dot(in, out), 0.5 * norm(in) * norm(out)) << c.name << " kinks at vertex " << k;
    }
  }
  expect_oracle_conformance(*o);
}

class SharedMeshes : public testing::TestWithParam<std::string> {};

TEST_P(SharedMeshes, Conformance) {
  RDMESH_REQUIRE_SHARED_DATA(path, "mesh/" + GetParam());
  const auto o = TriangleMeshOracle::from_file(path);
  EXPECT_GT(o->volume(), 0.0);
  expect_oracle_conformance(*o, 500);
}

INSTANTIATE_TEST_SUITE_P(TriangleMeshOracle, SharedMeshes,
                         testing::Values("cgal_cube.off", "cgal_anchor.off", "cgal_joint.off",
                                         "cgal_part.off", "cgal_pinion.off", "cgal_spool.off",
                                         "cgal_tripod.off", "cgal_wedge.off", "netgen_hinge.stl",
                                         "netgen_part1.stl"),
                         [](const auto& info) {
                           std::string s = info.param;
                           for (char& c : s)
                             c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return s;
                         });

}  // namespace
}  // namespace rdmesh
