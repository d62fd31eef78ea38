// measure_quality on the two-cube mesh: counts, exact volumes, Kuhn angles,
// topology, sampled distances with a scripted oracle, JSON and summary.
#include "rdmesh/quality_report.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "io/test_meshes.h"
#include "rdmesh/errors.h"

namespace rdmesh {
namespace {

constexpr double kS = 0.1;  // cube edge of the fixture

/// Oracle with scripted projections: patch 1 moves p by x(s - x) along z (so
/// the largest distance is at edge midpoints x = s/2), patch 2 never converges,
/// patch 3 throws OracleError. Counts calls per patch.
class ScriptedOracle : public DomainOracle {
 public:
  Box3 bounding_box() const override { return {{0, 0, 0}, {2 * kS, kS, kS}}; }
  Located locate(const Point3&, const std::optional<LocateHint>& = std::nullopt) const override {
    return {kOutside};
  }
  std::optional<SurfaceHit> intersect(const Point3&, const Point3&) const override { return {}; }
  std::vector<SubdomainInfo> subdomains() const override { return {}; }
  std::vector<PatchInfo> patches() const override { return {}; }
  std::vector<Point3> initial_points(PatchId) const override { return {}; }
  double tolerance() const override { return 1e-12; }
  std::optional<Point3> project(const Point3& p, PatchId patch) const override {
    ++calls[patch.value];
    if (patch.value == 1) return p + Point3{0, 0, p.x * (kS - p.x)};
    if (patch.value == 3) throw OracleError("scripted failure");
    return std::nullopt;
  }
  mutable std::atomic<int> calls[4] = {0, 0, 0, 0};
};

TEST(QualityReport, CountsVolumesAndAnglesOfTwoCubes) {
  const TetMesh mesh = testing::two_cube_mesh(kS);
  const QualityReport r = measure_quality(mesh, nullptr);
  EXPECT_EQ(r.vertices, 12u);
  EXPECT_EQ(r.tets, 12u);
  EXPECT_EQ(r.triangles, 22u);
  EXPECT_EQ(r.inverted_tets, 0u);
  // Kuhn tetrahedra (orthoschemes) have dihedral angles 45, 60 and 90 degrees,
  // and circumradius = half the cube diagonal = sqrt(3)/2 times the shortest edge.
  EXPECT_NEAR(r.min_dihedral_deg, 45.0, 1e-9);
  EXPECT_NEAR(r.max_dihedral_deg, 90.0, 1e-9);
  EXPECT_NEAR(r.max_radius_edge, std::sqrt(3.0) / 2.0, 1e-12);
  std::size_t histogram_total = 0;
  for (std::size_t n : r.dihedral_histogram) histogram_total += n;
  EXPECT_EQ(histogram_total, r.tets);
  EXPECT_EQ(r.dihedral_histogram[9], 12u);  // min angle 45 lands in [45, 50)

  ASSERT_EQ(r.subdomains.size(), 2u);
  EXPECT_EQ(r.subdomains[0].id, SubdomainId(1));
  EXPECT_EQ(r.subdomains[0].name, "left");
  EXPECT_EQ(r.subdomains[1].name, "right");
  for (const SubdomainStats& s : r.subdomains) {
    EXPECT_EQ(s.tets, 6u);
    EXPECT_NEAR(s.volume, kS * kS * kS, 1e-18);
  }
}

TEST(QualityReport, BoundaryTopologyPerPatchAndOverall) {
  const QualityReport r = measure_quality(testing::two_cube_mesh(kS), nullptr);
  ASSERT_EQ(r.patches.size(), 3u);
  const std::size_t expected_triangles[] = {10, 10, 2};
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(r.patches[k].id, PatchId(static_cast<int>(k) + 1));
    EXPECT_EQ(r.patches[k].triangles, expected_triangles[k]);
    EXPECT_EQ(r.patches[k].euler_characteristic, 1);  // every patch is a disk
    EXPECT_EQ(r.patches[k].max_distance, -1);         // no oracle: not measured
  }
  EXPECT_EQ(r.patches[2].name, "interface");
  // Closed box surface (chi = 2) plus the interface square glued along its
  // boundary: one more edge (its diagonal) and two more faces.
  EXPECT_EQ(r.boundary_euler_characteristic, 3);
  EXPECT_EQ(r.boundary_max_distance, -1);
  EXPECT_EQ(r.projection_failures, 0u);
}

TEST(QualityReport, SampledDistancesAndProjectionFailures) {
  const ScriptedOracle oracle;
  const QualityReport r = measure_quality(testing::two_cube_mesh(kS), &oracle);
  // Each skin is a disk of 8 vertices, 17 edges and 10 triangles: 35 distinct
  // samples; the interface square has 4 + 5 + 2 = 11.
  EXPECT_EQ(oracle.calls[1], 35);
  EXPECT_EQ(oracle.calls[2], 35);
  EXPECT_EQ(oracle.calls[3], 11);
  EXPECT_NEAR(r.patches[0].max_distance, kS * kS / 4, 1e-15);  // at midpoints x = s/2
  EXPECT_EQ(r.patches[0].projection_failures, 0u);
  EXPECT_EQ(r.patches[1].max_distance, -1);
  EXPECT_EQ(r.patches[1].projection_failures, 35u);
  EXPECT_EQ(r.patches[2].max_distance, -1);
  EXPECT_EQ(r.patches[2].projection_failures, 11u);
  EXPECT_EQ(r.projection_failures, 46u);
  EXPECT_NEAR(r.boundary_max_distance, kS * kS / 4, 1e-15);
}

TEST(QualityReport, InvertedTetIsCounted) {
  TetMesh mesh = testing::two_cube_mesh(kS);
  std::swap(mesh.tets[0][0], mesh.tets[0][1]);
  const QualityReport r = measure_quality(mesh, nullptr);
  EXPECT_EQ(r.inverted_tets, 1u);
  EXPECT_NEAR(r.subdomains[0].volume, kS * kS * kS * 4 / 6, 1e-18);  // one tet counts negatively
}

TEST(QualityReport, InconsistentMeshThrowsInternalError) {
  TetMesh mesh = testing::two_cube_mesh(kS);
  mesh.tets[3][2] = 12;  // one past the last vertex
  EXPECT_THROW(measure_quality(mesh, nullptr), InternalError);
  mesh = testing::two_cube_mesh(kS);
  mesh.triangle_patch.pop_back();
  EXPECT_THROW(measure_quality(mesh, nullptr), InternalError);
}

TEST(QualityReport, EmptyMesh) {
  const QualityReport r = measure_quality(TetMesh{}, nullptr);
  EXPECT_EQ(r.tets, 0u);
  EXPECT_EQ(r.min_dihedral_deg, 0);
  EXPECT_TRUE(r.subdomains.empty());
  EXPECT_NO_THROW(to_json(r).dump());
  EXPECT_FALSE(format_summary(r).empty());
}

TEST(QualityReport, JsonMirrorsTheStruct) {
  const ScriptedOracle oracle;
  const QualityReport r = measure_quality(testing::two_cube_mesh(kS), &oracle);
  const nlohmann::json j = nlohmann::json::parse(to_json(r).dump());  // survives text round trip
  EXPECT_EQ(j.at("vertices"), r.vertices);
  EXPECT_EQ(j.at("tets"), r.tets);
  EXPECT_EQ(j.at("triangles"), r.triangles);
  EXPECT_EQ(j.at("min_dihedral_deg").get<double>(), r.min_dihedral_deg);
  EXPECT_EQ(j.at("max_dihedral_deg").get<double>(), r.max_dihedral_deg);
  EXPECT_EQ(j.at("max_radius_edge").get<double>(), r.max_radius_edge);
  EXPECT_EQ(j.at("dihedral_histogram").get<std::vector<std::size_t>>(),
            std::vector<std::size_t>(r.dihedral_histogram.begin(), r.dihedral_histogram.end()));
  EXPECT_EQ(j.at("inverted_tets"), r.inverted_tets);
  EXPECT_EQ(j.at("boundary_max_distance").get<double>(), r.boundary_max_distance);
  EXPECT_EQ(j.at("boundary_euler_characteristic"), r.boundary_euler_characteristic);
  EXPECT_EQ(j.at("projection_failures"), r.projection_failures);
  ASSERT_EQ(j.at("subdomains").size(), r.subdomains.size());
  for (std::size_t i = 0; i < r.subdomains.size(); ++i) {
    const auto& s = j["subdomains"][i];
    EXPECT_EQ(s.at("id"), r.subdomains[i].id.value);
    EXPECT_EQ(s.at("name"), r.subdomains[i].name);
    EXPECT_EQ(s.at("tets"), r.subdomains[i].tets);
    EXPECT_EQ(s.at("volume").get<double>(), r.subdomains[i].volume);
  }
  ASSERT_EQ(j.at("patches").size(), r.patches.size());
  for (std::size_t i = 0; i < r.patches.size(); ++i) {
    const auto& p = j["patches"][i];
    EXPECT_EQ(p.at("id"), r.patches[i].id.value);
    EXPECT_EQ(p.at("name"), r.patches[i].name);
    EXPECT_EQ(p.at("triangles"), r.patches[i].triangles);
    EXPECT_EQ(p.at("euler_characteristic"), r.patches[i].euler_characteristic);
    EXPECT_EQ(p.at("max_distance").get<double>(), r.patches[i].max_distance);
    EXPECT_EQ(p.at("projection_failures"), r.patches[i].projection_failures);
  }
}

TEST(QualityReport, NonFiniteRadiusEdgeBecomesJsonNull) {
  QualityReport r;
  r.max_radius_edge = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(to_json(r).at("max_radius_edge").is_null());
}

TEST(QualityReport, SummaryNamesEveryLabel) {
  const QualityReport r = measure_quality(testing::two_cube_mesh(kS), nullptr);
  const std::string s = format_summary(r);
  for (const char* text : {"12 vertices", "12 tetrahedra", "22 boundary triangles", "left", "right",
                           "left skin", "right skin", "interface", "45.00", "90.00"}) {
    EXPECT_NE(s.find(text), std::string::npos) << "missing '" << text << "' in\n" << s;
  }
  EXPECT_EQ(s.back(), '\n');
}

}  // namespace
}  // namespace rdmesh
