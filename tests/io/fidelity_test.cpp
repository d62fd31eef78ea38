// The fidelity check (io/include/rdmesh/fidelity.h) on hand-made meshes whose
// volumes, patches and chains are known: a mesh that matches its model passes;
// a lost piece of volume, a patch without triangles or a broken curve fails,
// named in one problem each.
#include "rdmesh/fidelity.h"

#include <gtest/gtest.h>

#include "rdmesh/quality_report.h"
#include "test_meshes.h"

namespace rdmesh {
namespace {

/// The two cubes of side s: volume s^3 each; patch areas 5 s^2, 5 s^2 and s^2.
ModelMeasures two_cube_model(double s, double left_volume) {
  ModelMeasures m;
  m.subdomain_volume = {left_volume, s * s * s};
  m.patch_area = {5 * s * s, 5 * s * s, s * s};
  return m;
}

TEST(Fidelity, AMeshThatMatchesItsModelPasses) {
  const TetMesh mesh = testing::two_cube_mesh(0.1);
  const QualityReport q = measure_quality(mesh, nullptr);
  const FidelityReport r =
      check_fidelity(q, two_cube_model(0.1, 1e-3), mesh.patches, mesh.curves, 1e-3);
  EXPECT_TRUE(r.passed) << summarize_problems(r);
  ASSERT_EQ(r.volumes.size(), 2u);
  EXPECT_NEAR(r.volumes[0].mesh_volume, 1e-3, 1e-15);
  // Tolerance: facet distance x area of the patches around the subdomain.
  EXPECT_NEAR(r.volumes[0].tolerance, 1e-3 * 6 * 0.01 + 1e-12, 1e-15);
  EXPECT_TRUE(r.problems.empty());
}

TEST(Fidelity, WithoutTheModelsAreasTheMeshsOwnServe) {
  const TetMesh mesh = testing::two_cube_mesh(0.1);
  const QualityReport q = measure_quality(mesh, nullptr);
  ModelMeasures model = two_cube_model(0.1, 1e-3);
  model.patch_area.clear();
  const FidelityReport r = check_fidelity(q, model, mesh.patches, mesh.curves, 1e-3);
  ASSERT_EQ(r.volumes.size(), 2u);
  // The left cube's skin (5 squares) and the interface: 0.06, as measured on the mesh.
  EXPECT_NEAR(r.volumes[0].tolerance, 1e-3 * 0.06 + 1e-12, 1e-15);
  EXPECT_TRUE(r.passed);
}

TEST(Fidelity, AVolumeBeyondTheToleranceFailsAndIsNamed) {
  const TetMesh mesh = testing::two_cube_mesh(0.1);
  const QualityReport q = measure_quality(mesh, nullptr);
  // The model's left solid is twice the mesh's: half of it was lost.
  const FidelityReport r =
      check_fidelity(q, two_cube_model(0.1, 2e-3), mesh.patches, mesh.curves, 1e-3);
  EXPECT_FALSE(r.passed);
  ASSERT_EQ(r.problems.size(), 1u);
  EXPECT_NE(r.problems[0].find("subdomain 1 (left): volume 0.001, model 0.002 (-50.0%"),
            std::string::npos)
      << r.problems[0];
  EXPECT_FALSE(r.volumes[0].passed);
  EXPECT_TRUE(r.volumes[1].passed);
  // At a facet distance of 0.1 the areas would allow 0.006, more than the
  // solid: the tolerance stops at 10% of the volume, and half of it lost fails.
  const FidelityReport coarse =
      check_fidelity(q, two_cube_model(0.1, 2e-3), mesh.patches, mesh.curves, 0.1);
  EXPECT_FALSE(coarse.passed);
  EXPECT_NEAR(coarse.volumes[0].tolerance, kMaxVolumeDeviation * 2e-3 + 2e-12, 1e-15);
  // 5% lost passes there.
  EXPECT_TRUE(
      check_fidelity(q, two_cube_model(0.1, 1.05e-3), mesh.patches, mesh.curves, 0.1).passed);
}

TEST(Fidelity, AVaryingFacetDistanceGivesEachSubdomainItsOwnTolerance) {
  // Fine on the left cube (x <= s), coarse elsewhere: the left skin (patch 1)
  // and the interface x = s (patch 3) get the fine value, the right skin the
  // coarse one.
  const double s = 0.1;
  const TetMesh mesh = testing::two_cube_mesh(s);
  const ScalarField d{0.0, [s](const Point3& p) { return p.x < s + 1e-12 ? 1e-4 : 1e-2; }};
  const std::vector<double> per_patch = patch_facet_distances(mesh, d);
  ASSERT_EQ(per_patch.size(), 3u);
  EXPECT_DOUBLE_EQ(per_patch[0], 1e-4);
  EXPECT_DOUBLE_EQ(per_patch[1], 1e-2);
  EXPECT_DOUBLE_EQ(per_patch[2], 1e-4);
  const QualityReport q = measure_quality(mesh, nullptr);
  const ModelMeasures model = two_cube_model(s, 1.05e-3);  // the left cube lost 5% of it
  const FidelityReport r = check_fidelity(q, model, mesh.patches, mesh.curves, per_patch);
  ASSERT_EQ(r.volumes.size(), 2u);
  // Left: 1e-4 x (its skin, 5 s^2, and the interface, s^2).
  EXPECT_NEAR(r.volumes[0].tolerance, 1e-4 * 6 * s * s + 1.05e-12, 1e-15);
  EXPECT_FALSE(r.volumes[0].passed);
  // Right: 1e-2 x 5 s^2 + 1e-4 x s^2 = 5.01e-4, above 10% of s^3: capped.
  EXPECT_NEAR(r.volumes[1].tolerance, 1e-4 + 1e-12, 1e-15);
  EXPECT_TRUE(r.volumes[1].passed);
  // At the coarse value everywhere the same mesh passes (6e-4, capped at 1.05e-4).
  EXPECT_TRUE(check_fidelity(q, model, mesh.patches, mesh.curves, 1e-2).passed);
  EXPECT_EQ(patch_facet_distances(mesh, ScalarField::uniform(0.5)), std::vector<double>(3, 0.5));
}

TEST(Fidelity, AWholeDomainVolumeIsCheckedWhenSubdomainsAreUnknown) {
  const TetMesh mesh = testing::two_cube_mesh(0.1);
  const QualityReport q = measure_quality(mesh, nullptr);
  ModelMeasures m = two_cube_model(0.1, 1e-3);
  m.subdomain_volume.clear();
  m.total_volume = 3e-3;
  const FidelityReport r = check_fidelity(q, m, mesh.patches, mesh.curves, 1e-3);
  ASSERT_EQ(r.volumes.size(), 1u);
  EXPECT_EQ(r.volumes[0].id, kOutside);
  EXPECT_NEAR(r.volumes[0].mesh_volume, 2e-3, 1e-15);
  EXPECT_FALSE(r.passed);
  m.total_volume = 2e-3;
  EXPECT_TRUE(check_fidelity(q, m, mesh.patches, mesh.curves, 1e-3).passed);
}

TEST(Fidelity, APatchWithoutTrianglesAndABrokenCurveFail) {
  TetMesh mesh = testing::featured_two_cube_mesh(0.1);
  const ModelMeasures model = two_cube_model(0.1, 1e-3);
  std::vector<PatchInfo> patches = mesh.patches;
  patches.push_back({PatchId(4), "lost face", SubdomainId(1), SubdomainId(2)});
  const QualityReport whole = measure_quality(mesh, nullptr);
  FidelityReport r = check_fidelity(whole, model, patches, mesh.curves, 1e-3);
  ASSERT_EQ(r.missing_patches.size(), 1u);
  EXPECT_EQ(r.missing_patches[0], PatchId(4));
  EXPECT_TRUE(r.broken_curves.empty());
  // Drop one of curve 1's two edges: it is no longer a chain from corner to corner.
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    if (mesh.edge_curve[e] == CurveId(1)) {
      mesh.edges.erase(mesh.edges.begin() + static_cast<long>(e));
      mesh.edge_curve.erase(mesh.edge_curve.begin() + static_cast<long>(e));
      break;
    }
  }
  r = check_fidelity(measure_quality(mesh, nullptr), model, mesh.patches, mesh.curves, 1e-3);
  EXPECT_FALSE(r.passed);
  ASSERT_EQ(r.broken_curves.size(), 1u);
  EXPECT_EQ(r.broken_curves[0], CurveId(1));
  EXPECT_NE(summarize_problems(r).find("is not one chain of edges"), std::string::npos);
  const nlohmann::json j = to_json(r);
  EXPECT_FALSE(j["passed"].get<bool>());
  EXPECT_EQ(j["broken_curves"][0].get<int>(), 1);
}

TEST(Fidelity, ASliverFaceBoundedByCurvesBelowTheMinimumSizeIsListedNotFailed) {
  const TetMesh mesh = testing::featured_two_cube_mesh(0.1);
  const ModelMeasures model = two_cube_model(0.1, 1e-3);
  std::vector<PatchInfo> patches = mesh.patches;
  patches.push_back({PatchId(4), "sliver", SubdomainId(1), SubdomainId(2)});
  std::vector<CurveInfo> curves = mesh.curves;
  CurveInfo edge;
  edge.id = CurveId(static_cast<int>(curves.size()) + 1);
  edge.name = "sliver edge";
  edge.patches = {PatchId(1), PatchId(4)};
  curves.push_back(edge);
  const QualityReport q = measure_quality(mesh, nullptr);
  // Its only curve is below the minimum size (and not meshed): listed, passes.
  FidelityReport r = check_fidelity(q, model, patches, curves, 1e-3, {edge.id});
  EXPECT_TRUE(r.passed) << summarize_problems(r);
  ASSERT_EQ(r.unresolved_patches.size(), 1u);
  EXPECT_EQ(r.unresolved_patches[0], PatchId(4));
  EXPECT_EQ(to_json(r)["patches_below_min_size"][0].get<int>(), 4);
  // A resolved curve among its curves: the face was missed, a failure.
  curves.back().patches.push_back(PatchId(2));
  curves[0].patches.push_back(PatchId(4));
  r = check_fidelity(q, model, patches, curves, 1e-3, {edge.id});
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.missing_patches, std::vector<PatchId>{PatchId(4)});
}

TEST(Fidelity, TheSummaryNamesThreeProblemsAndCountsTheRest) {
  FidelityReport r;
  r.problems = {"a", "b", "c", "d", "e"};
  EXPECT_EQ(summarize_problems(r), "a; b; c; and 2 more");
}

}  // namespace
}  // namespace rdmesh
