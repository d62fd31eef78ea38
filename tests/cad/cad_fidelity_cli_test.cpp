// The fidelity check on CAD runs (io/include/rdmesh/fidelity.h): a mesh that
// does not match the model is exit 4 with one error line naming what is
// wrong, and no mesh file unless --keep-bad-mesh; a good one is exit 0 and its
// report shows the volumes compared.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli/cli_runner.h"
#include "shared_data.h"

namespace rdmesh::test {
namespace {

/// The lines of `output` that start with "rdmesh: error:".
std::vector<std::string> error_lines(const std::string& output) {
  std::vector<std::string> lines;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("rdmesh: error:", 0) == 0) lines.push_back(line);
  }
  return lines;
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(CadFidelity, AGoodMeshPassesAndItsReportComparesTheVolumes) {
  ScratchDir dir;
  const std::string step = source_path("samples/plate_with_hole.step");
  const CliRun run = run_cli("'" + step + "' -o part.mesh --report r.json -q", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json f = read_json(dir.file("r.json"))["fidelity"];
  EXPECT_TRUE(f["passed"].get<bool>());
  ASSERT_EQ(f["volumes"].size(), 1u);
  const double model = f["volumes"][0]["model"], mesh = f["volumes"][0]["mesh"];
  EXPECT_NEAR(model, 3497.345, 1e-3);  // BRepGProp's volume of the plate
  EXPECT_LE(std::fabs(mesh - model), f["volumes"][0]["tolerance"].get<double>());
  EXPECT_GT(mesh, 0.9 * model);
}

TEST(CadFidelity, ACrackFaceInsideTheSolidIsNotABoundary) {
  // gmsh_crack1.brep: a unit cube with an INTERNAL face (a crack). Taken for a
  // boundary between the solid and the outside, it cost 8% of the volume.
  RDMESH_REQUIRE_SHARED_DATA(brep, "brep/gmsh_crack1.brep");
  ScratchDir dir;
  const CliRun run = run_cli("'" + brep + "' -o crack.mesh -q --report r.json", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json j = read_json(dir.file("r.json"));
  EXPECT_EQ(j["patches"].size(), 6u);  // the cube's faces, not the crack
  EXPECT_NEAR(j["fidelity"]["volumes"][0]["mesh"].get<double>(), 1.0, 1e-9);
}

TEST(CadFidelity, ASlenderPartMeshesWithinTheCheckAtTheDefaults) {
  // bm2_ec_leverrod-A: a rod 10 m long and 32 mm thick. At 356f17e the run said
  // success with 72% of the volume missing; with sizes alone following the
  // rod's thickness its section was a hexagon (-17%), and the check, whose
  // tolerance followed the default facet distance (51 mm, more than the rod is
  // thick), passed it. The facet distance now follows the thickness too.
  RDMESH_REQUIRE_SHARED_DATA(step, "step/occtdata_bm2_ec_leverrod-A.stp");
  ScratchDir dir;
  const CliRun run = run_cli("'" + step + "' -o rod.mesh -q --report r.json", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json f = read_json(dir.file("r.json"))["fidelity"];
  EXPECT_TRUE(f["passed"].get<bool>());
  const double model = f["volumes"][0]["model"], mesh = f["volumes"][0]["mesh"];
  EXPECT_NEAR(model, 5.2155e6, 1e3);  // BRepGProp
  EXPECT_LE(std::fabs(mesh - model), f["volumes"][0]["tolerance"].get<double>());
  EXPECT_LT(f["volumes"][0]["tolerance"].get<double>(), 0.1 * model);
}

TEST(CadFidelity, AnAssemblyWithPartsAHairApartMeshesWithinTheCheckAtTheDefaults) {
  // occtdata_as1_motor.step: 35 solids, parts placed 0.01 apart in a
  // 300,000-unit model. The exact fuse cut faces 0.01 wide along whole circles
  // and the run was still refining after 150 s with 1.77M vertices; fused as
  // touching, it meshes in about 20 s.
  RDMESH_REQUIRE_SHARED_DATA(step, "step/occtdata_as1_motor.step");
  ScratchDir dir;
  const CliRun run = run_cli("'" + step + "' -o motor.mesh -q --report r.json", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json j = read_json(dir.file("r.json"));
  const nlohmann::json& f = j["fidelity"];
  EXPECT_TRUE(f["passed"].get<bool>());
  ASSERT_EQ(f["volumes"].size(), 35u);
  int meshed = 0;
  for (const nlohmann::json& v : f["volumes"]) {
    const double model = v["model"], mesh = v["mesh"];
    EXPECT_LE(std::fabs(mesh - model), v["tolerance"].get<double>()) << v["name"];
    if (model > 0) ++meshed;
  }
  EXPECT_EQ(meshed, 17);  // the other 18 lie inside earlier solids
  // BRepGProp's volume of a part that touches no other.
  EXPECT_NEAR(f["volumes"][2]["model"].get<double>(), 5.424e13, 1e-9 * 5.424e13);
  EXPECT_LT(j["tets"].get<double>(), 1e6);
}

TEST(CadFidelity, InAnAssemblyTheMinimumSizeFollowsTheThinnestPart) {
  // occt_Axis_of_bearing.brep: balls of radius 2 on their races in a model
  // 147 long. The gap around each contact thins out to nothing and refinement
  // follows it down to the minimum size: at 1e-4 of the diagonal (0.0147),
  // 1.2M tetrahedra in 90 s. The minimum size is 1/50 of the thinnest part's
  // thickness 2V/A (a ball's: 2r/3), as for a single part thinner than that.
  RDMESH_REQUIRE_SHARED_DATA(brep, "brep/occt_Axis_of_bearing.brep");
  ScratchDir dir;
  const CliRun run =
      run_cli("'" + brep + "' -o b.mesh -q --time-limit 0.01 --report r.json", dir.path());
  EXPECT_EQ(run.exit_code, 4) << run.output;  // stopped: only the criteria are looked at
  const nlohmann::json j = read_json(dir.file("r.json"));
  EXPECT_NEAR(j["criteria"]["min_size"].get<double>(), 2.0 * 2 / 3 / 50, 1e-6);
}

TEST(CadFidelity, AMeshThatLosesPartOfTheModelIsExitFourWithoutOutput) {
  // The same rod at a size of 500 mm, asked for: no cell inside the rod, 72% of
  // the volume lost (as every run did at 356f17e).
  RDMESH_REQUIRE_SHARED_DATA(step, "step/occtdata_bm2_ec_leverrod-A.stp");
  ScratchDir dir;
  CliRun run = run_cli("'" + step + "' -o rod.mesh -q --size 500", dir.path());
  EXPECT_EQ(run.exit_code, 4) << run.output;
  std::vector<std::string> errors = error_lines(run.output);
  ASSERT_EQ(errors.size(), 1u) << run.output;
  EXPECT_NE(errors[0].find(step + ": the mesh does not match the model: "), std::string::npos)
      << errors[0];
  EXPECT_NE(errors[0].find("--keep-bad-mesh"), std::string::npos) << errors[0];
  EXPECT_FALSE(std::filesystem::exists(dir.file("rod.mesh")));

  run = run_cli("'" + step + "' -o rod.mesh -q --size 500 --keep-bad-mesh --report r.json",
                dir.path());
  EXPECT_EQ(run.exit_code, 4) << run.output;
  EXPECT_TRUE(std::filesystem::exists(dir.file("rod.mesh")));
  const nlohmann::json f = read_json(dir.file("r.json"))["fidelity"];
  EXPECT_FALSE(f["passed"].get<bool>());
  EXPECT_FALSE(f["problems"].empty());
}

TEST(CadFidelity, TheTimeLimitStopsRefinementAndWritesNothingUnlessAsked) {
  ScratchDir dir;
  const std::string step = source_path("samples/plate_with_hole.step");
  // A size that needs about a million tetrahedra, stopped after 0.3 s.
  const std::string args = "'" + step + "' -o part.mesh -q --size 0.25 --time-limit 0.3";
  CliRun run = run_cli(args, dir.path());
  EXPECT_EQ(run.exit_code, 4) << run.output;
  const std::vector<std::string> errors = error_lines(run.output);
  ASSERT_EQ(errors.size(), 1u) << run.output;
  EXPECT_NE(errors[0].find("refinement stopped at the time limit (0.3 s)"), std::string::npos)
      << errors[0];
  EXPECT_FALSE(std::filesystem::exists(dir.file("part.mesh")));
  run = run_cli(args + " --keep-bad-mesh --report r.json", dir.path());
  EXPECT_EQ(run.exit_code, 4) << run.output;
  EXPECT_TRUE(std::filesystem::exists(dir.file("part.mesh")));
  const nlohmann::json j = read_json(dir.file("r.json"));
  EXPECT_TRUE(j["refinement"]["time_limit_reached"].get<bool>());
  EXPECT_GT(j["refinement"]["elements_left"].get<int>(), 0);
  EXPECT_LT(j["seconds"]["refine"].get<double>(), 2.0);
}

}  // namespace
}  // namespace rdmesh::test
