// measure_quality on meshes with sharp features: per-curve edge counts, chain
// shape against the curve's corners, sampled distance with a scripted oracle
// curve, corners found, JSON and summary.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "io/test_meshes.h"
#include "rdmesh/errors.h"
#include "rdmesh/quality_report.h"

namespace rdmesh {
namespace {

constexpr double kS = 0.1;

/// Bulge of curve `id` at its middle.
double bulge(int id) { return 1e-3 * id; }

/// The segment a -> b (t in [0, 1]) bent by bulge * 4t(1-t) along a unit
/// normal. closest() is scripted: it returns the parameter of the projection on
/// the chord, so a sample at chord parameter t is exactly bulge * 4t(1-t) away
/// from point(closest(sample)). Counts its closest() calls and records the range.
class BentSegment : public Curve {
 public:
  BentSegment(Point3 a, Point3 b, double bulge, bool nan_points = false)
      : a_(a), b_(b), bulge_(bulge), nan_points_(nan_points) {
    const Point3 d = b - a;
    const Point3 axis = std::abs(d.z) < 0.5 * norm(d) ? Point3{0, 0, 1} : Point3{1, 0, 0};
    const Point3 n = cross(d, axis);
    normal_ = (1 / norm(n)) * n;
  }
  Point3 point(double t) const override {
    if (nan_points_) return {std::nan(""), 0, 0};
    return a_ + t * (b_ - a_) + (bulge_ * 4 * t * (1 - t)) * normal_;
  }
  double length(double ta, double tb) const override { return (tb - ta) * distance(a_, b_); }
  double parameter_at_length(double ta, double s) const override {
    return std::min(1.0, ta + s / distance(a_, b_));
  }
  double closest(const Point3& p, double ta, double tb) const override {
    ++calls;
    last_range[0] = ta;
    last_range[1] = tb;
    const Point3 d = b_ - a_;
    return std::clamp(dot(p - a_, d) / squared_norm(d), ta, tb);
  }
  std::vector<double> plane_crossings(const Point3&, double, double, double) const override {
    return {};
  }
  /// The parabola's: |gamma' x gamma''| / |gamma'|^3 with gamma'' = -8 bulge n.
  double curvature(double t) const override {
    const Point3 d1 = (b_ - a_) + (bulge_ * 4 * (1 - 2 * t)) * normal_;
    return 8 * std::abs(bulge_) * distance(a_, b_) / std::pow(norm(d1), 3);
  }
  mutable std::atomic<int> calls{0};
  mutable double last_range[2] = {-1, -1};

 private:
  Point3 a_, b_, normal_;
  double bulge_;
  bool nan_points_;
};

/// Oracle with the 12 box edges of featured_two_cube_mesh as bent segments;
/// curve 13 (the rim) is unknown (curve() throws OracleError). Optionally the
/// points of curve `nan_curve` are NaN.
class FeatureOracle : public DomainOracle {
 public:
  explicit FeatureOracle(const TetMesh& mesh, int nan_curve = 0) : info_(mesh.curves) {
    for (const CurveInfo& c : mesh.curves) {
      if (c.closed) continue;
      const Point3 a = mesh.corners[static_cast<std::size_t>(c.start.value - 1)].point;
      const Point3 b = mesh.corners[static_cast<std::size_t>(c.end.value - 1)].point;
      curves_.push_back(
          std::make_unique<BentSegment>(a, b, bulge(c.id.value), c.id.value == nan_curve));
    }
  }
  Box3 bounding_box() const override { return {{0, 0, 0}, {2 * kS, kS, kS}}; }
  Located locate(const Point3&, const std::optional<LocateHint>& = std::nullopt) const override {
    return {kOutside};
  }
  std::optional<SurfaceHit> intersect(const Point3&, const Point3&) const override { return {}; }
  std::vector<SubdomainInfo> subdomains() const override { return {}; }
  std::vector<PatchInfo> patches() const override { return {}; }
  std::vector<Point3> initial_points(PatchId) const override { return {}; }
  std::optional<Point3> project(const Point3& p, PatchId) const override { return p; }
  double tolerance() const override { return 1e-12; }
  std::vector<CornerInfo> corners() const override { return {}; }
  std::vector<CurveInfo> curves() const override { return info_; }
  const Curve& curve(CurveId id) const override {
    if (id.value < 1 || id.value > static_cast<int>(curves_.size())) {
      throw OracleError("unknown curve " + std::to_string(id.value));
    }
    return *curves_[static_cast<std::size_t>(id.value - 1)];
  }
  const BentSegment& segment(int id) const { return *curves_[static_cast<std::size_t>(id - 1)]; }

 private:
  std::vector<CurveInfo> info_;
  std::vector<std::unique_ptr<BentSegment>> curves_;
};

TEST(FeatureReport, CountsChainsAndCornersOfTheFixture) {
  const QualityReport r = measure_quality(testing::featured_two_cube_mesh(kS), nullptr);
  ASSERT_EQ(r.curves.size(), 13u);
  for (std::size_t k = 0; k < 13; ++k) {
    const CurveStats& c = r.curves[k];
    EXPECT_EQ(c.id, CurveId(static_cast<int>(k) + 1));
    EXPECT_EQ(c.edges, k < 4 ? 2u : k < 12 ? 1u : 4u) << c.name;
    EXPECT_TRUE(c.is_chain) << c.name;
    EXPECT_EQ(c.max_distance, -1);
    EXPECT_EQ(c.projection_failures, 0u);
  }
  EXPECT_EQ(r.curves[0].name, "x00");
  EXPECT_EQ(r.curves[12].name, "rim");
  EXPECT_EQ(r.corners_present, 8u);
  EXPECT_EQ(r.corners_expected, 8u);
  EXPECT_EQ(r.feature_max_distance, -1);
}

TEST(FeatureReport, SampledDistanceToTheCurves) {
  const TetMesh mesh = testing::featured_two_cube_mesh(kS);
  const FeatureOracle oracle(mesh);
  const QualityReport r = measure_quality(mesh, &oracle);
  for (int id = 1; id <= 12; ++id) {
    const CurveStats& c = r.curves[static_cast<std::size_t>(id - 1)];
    // The largest bend is at chord parameter 1/2: the middle vertex of an x
    // curve, the midpoint of a one-edge curve.
    EXPECT_NEAR(c.max_distance, bulge(id), 1e-15) << c.name;
    EXPECT_EQ(c.projection_failures, 0u);
    // Each vertex once, 3 samples per edge: 3 + 6 for two edges, 2 + 3 for one.
    EXPECT_EQ(oracle.segment(id).calls, id <= 4 ? 9 : 5) << c.name;
    EXPECT_EQ(oracle.segment(id).last_range[0], 0.0);
    EXPECT_EQ(oracle.segment(id).last_range[1], 1.0);
  }
  // The rim is unknown to the oracle: its 4 vertices and 12 edge samples fail.
  EXPECT_EQ(r.curves[12].max_distance, -1);
  EXPECT_EQ(r.curves[12].projection_failures, 16u);
  EXPECT_NEAR(r.feature_max_distance, bulge(12), 1e-15);
}

TEST(FeatureReport, NonFinitePointsCountAsFailures) {
  const TetMesh mesh = testing::featured_two_cube_mesh(kS);
  const FeatureOracle oracle(mesh, 12);
  const QualityReport r = measure_quality(mesh, &oracle);
  EXPECT_EQ(r.curves[11].max_distance, -1);
  EXPECT_EQ(r.curves[11].projection_failures, 5u);
  EXPECT_NEAR(r.feature_max_distance, bulge(11), 1e-15);
}

TEST(FeatureReport, MissingEdgesCornersAndBranches) {
  TetMesh mesh = testing::featured_two_cube_mesh(kS);
  // x00: drop its second edge. What remains is a simple path, but it does not
  // reach corner 2, so it is not the curve's chain.
  mesh.edges.erase(mesh.edges.begin() + 1);
  mesh.edge_curve.erase(mesh.edge_curve.begin() + 1);
  // x10 (edges 1 and 2 now): reversing an edge keeps a chain (orientation is not checked).
  std::swap(mesh.edges[1][0], mesh.edges[1][1]);
  // y00 (one edge 0 -> 3): two more edges at its start corner make it branch.
  mesh.edges.insert(mesh.edges.end(), {{0, 1}, {0, 6}});
  mesh.edge_curve.insert(mesh.edge_curve.end(), 2, CurveId(5));
  // The rim loses an edge: a path, not the closed chain it should be.
  const auto rim = std::find(mesh.edge_curve.begin(), mesh.edge_curve.end(), CurveId(13));
  mesh.edges.erase(mesh.edges.begin() + (rim - mesh.edge_curve.begin()));
  mesh.edge_curve.erase(rim);
  // Corner 8 has no vertex: the three curves ending there fail.
  mesh.corner_vertices.pop_back();
  mesh.corner_ids.pop_back();
  // A curve not listed in mesh.curves, made of a cycle: accepted either way.
  mesh.edges.insert(mesh.edges.end(), {{0, 3}, {3, 9}, {9, 0}});
  mesh.edge_curve.insert(mesh.edge_curve.end(), 3, CurveId(20));

  const QualityReport r = measure_quality(mesh, nullptr);
  ASSERT_EQ(r.curves.size(), 14u);
  std::vector<bool> chain;
  for (const CurveStats& c : r.curves) chain.push_back(c.is_chain);
  const std::vector<bool> expected{false, true, true, false, false, true,  true,
                                   false, true, true, true,  false, false, true};
  EXPECT_EQ(chain, expected);
  EXPECT_EQ(r.curves[0].edges, 1u);
  EXPECT_EQ(r.curves[4].edges, 3u);
  EXPECT_EQ(r.curves[12].edges, 3u);
  EXPECT_EQ(r.curves[13].id, CurveId(20));
  EXPECT_EQ(r.curves[13].name, "");
  EXPECT_EQ(r.corners_present, 7u);
  EXPECT_EQ(r.corners_expected, 8u);
}

TEST(FeatureReport, OpenCurveStartingAndEndingAtOneCorner) {
  TetMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.edges = {{0, 1}, {1, 2}, {2, 0}};
  mesh.edge_curve.assign(3, CurveId(1));
  mesh.curves = {{CurveId(1), "drop", false, 0, 1, CornerId(1), CornerId(1), {}}};
  mesh.corners = {{CornerId(1), {0, 0, 0}, {CurveId(1)}, {}}};
  mesh.corner_vertices = {0};
  mesh.corner_ids = {CornerId(1)};
  EXPECT_TRUE(measure_quality(mesh, nullptr).curves.at(0).is_chain);
  mesh.corner_vertices = {3};  // the corner is off the loop
  EXPECT_FALSE(measure_quality(mesh, nullptr).curves.at(0).is_chain);
}

TEST(FeatureReport, InconsistentFeaturesThrowInternalError) {
  TetMesh mesh = testing::featured_two_cube_mesh(kS);
  mesh.edge_curve.pop_back();
  EXPECT_THROW(measure_quality(mesh, nullptr), InternalError);
  mesh = testing::featured_two_cube_mesh(kS);
  mesh.corner_vertices[0] = 99;
  EXPECT_THROW(measure_quality(mesh, nullptr), InternalError);
}

TEST(FeatureReport, JsonHasTheFeatureKeys) {
  const TetMesh mesh = testing::featured_two_cube_mesh(kS);
  const FeatureOracle oracle(mesh);
  const QualityReport r = measure_quality(mesh, &oracle);
  const nlohmann::json j = nlohmann::json::parse(to_json(r).dump());
  EXPECT_EQ(j.at("corners_present"), 8);
  EXPECT_EQ(j.at("corners_expected"), 8);
  EXPECT_EQ(j.at("feature_max_distance").get<double>(), r.feature_max_distance);
  ASSERT_EQ(j.at("curves").size(), 13u);
  for (std::size_t k = 0; k < r.curves.size(); ++k) {
    const auto& c = j["curves"][k];
    EXPECT_EQ(c.size(), 6u);
    EXPECT_EQ(c.at("id"), r.curves[k].id.value);
    EXPECT_EQ(c.at("name"), r.curves[k].name);
    EXPECT_EQ(c.at("edges"), r.curves[k].edges);
    EXPECT_EQ(c.at("is_chain"), r.curves[k].is_chain);
    EXPECT_EQ(c.at("max_distance").get<double>(), r.curves[k].max_distance);
    EXPECT_EQ(c.at("projection_failures"), r.curves[k].projection_failures);
  }
  // Without features the keys are still there, empty.
  const nlohmann::json plain = to_json(measure_quality(testing::two_cube_mesh(kS), nullptr));
  EXPECT_TRUE(plain.at("curves").empty());
  EXPECT_EQ(plain.at("corners_expected"), 0);
  EXPECT_EQ(plain.at("feature_max_distance").get<double>(), -1);
}

TEST(FeatureReport, SummaryListsCurvesOnlyWhenThereAreSome) {
  TetMesh mesh = testing::featured_two_cube_mesh(kS);
  mesh.corner_vertices.pop_back();
  mesh.corner_ids.pop_back();
  const std::string s = format_summary(measure_quality(mesh, nullptr));
  for (const char* text : {"Features: 13 curves (3 not a simple chain), 7 of 8 corners", "x00",
                           "rim", "z11", "chain", " NO "}) {
    EXPECT_NE(s.find(text), std::string::npos) << "missing '" << text << "' in\n" << s;
  }
  const std::string plain = format_summary(measure_quality(testing::two_cube_mesh(kS), nullptr));
  EXPECT_EQ(plain.find("Features"), std::string::npos) << plain;
  EXPECT_EQ(plain.find("curve"), std::string::npos) << plain;
  EXPECT_EQ(s.substr(0, plain.size()), plain);  // the feature part is appended
}

}  // namespace
}  // namespace rdmesh
