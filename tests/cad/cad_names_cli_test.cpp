// Names and colours of a STEP file through the command line: the solids'
// physical names in the .vtu field data, the colours in the report, and what
// --heal says it did.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/cli_runner.h"
#include "shared_data.h"

namespace rdmesh::test {
namespace {

TEST(CadNamesCli, NamesInTheVtuColoursInTheReportAndWhatHealingDid) {
  RDMESH_REQUIRE_SHARED_DATA(path, "step/cadquery_red_cube_blue_cylinder.step");
  ScratchDir dir;
  const CliRun run =
      run_cli("'" + path + "' -o cq.vtu --report r.json --heal --size 4", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  // --heal says what it changed (or that it changed nothing), with the tolerances.
  EXPECT_NE(run.output.find("healing: "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("largest vertex/edge tolerance"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("fixed the shape"), std::string::npos) << run.output;

  const std::string vtu = read_file(dir.file("cq.vtu"));
  for (const char* name : {"Name=\"red_cube\"", "Name=\"blue_cylinder\""}) {
    EXPECT_NE(vtu.find(name), std::string::npos) << name;
  }
  std::ifstream in(dir.file("r.json"));
  const nlohmann::json r = nlohmann::json::parse(in);
  std::map<std::string, int> names;
  for (const auto& s : r.at("subdomains")) ++names[s.at("name").get<std::string>()];
  EXPECT_EQ(names, (std::map<std::string, int>{{"blue_cylinder", 1}, {"red_cube", 1}}));
  std::map<std::string, int> colors;
  for (const auto& p : r.at("patches")) ++colors[p.value("color", std::string("none"))];
  EXPECT_EQ(colors.count("none"), 0u) << r.at("patches");
  EXPECT_GT(colors["#dd5228"], 0);
  EXPECT_GT(colors["#3b61b4"], 0);
}

}  // namespace
}  // namespace rdmesh::test
