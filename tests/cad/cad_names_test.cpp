// Names and colours from STEP files: assembly parts named after their products,
// unique names for repeated instances, face colours, and all of it surviving
// the hand-off from the isolated reading child.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "rdmesh/cad_oracle.h"
#include "shared_data.h"

namespace rdmesh {
namespace {

std::unique_ptr<CadOracle> load(const std::string& path, bool isolate) {
  CadOptions options;
  options.isolate = isolate;
  return load_cad_file(path, options);
}

/// "nut_3" -> "nut"; "rod" -> "rod".
std::string base_name(const std::string& name) {
  const auto at = name.rfind('_');
  if (at == std::string::npos ||
      name.find_first_not_of("0123456789", at + 1) != std::string::npos) {
    return name;
  }
  return name.substr(0, at);
}

TEST(CadNames, AssemblySolidsAreNamedAfterTheirProductsAndStayUnique) {
  // The CAx-IF as1 assembly: 18 solid instances of 5 parts (AP203).
  RDMESH_REQUIRE_SHARED_DATA(path, "step/gmsh_as1-tu-203.stp");
  for (const bool isolate : {true, false}) {
    const auto oracle = load(path, isolate);
    const std::vector<SubdomainInfo> solids = oracle->subdomains();
    ASSERT_EQ(solids.size(), 18u);
    std::set<std::string> names;
    std::map<std::string, int> parts;
    for (const SubdomainInfo& s : solids) {
      EXPECT_TRUE(names.insert(s.name).second) << "two solids named " << s.name;
      ++parts[base_name(s.name)];
    }
    // 6 nuts, 6 bolts... as the file instantiates them; no solid left as solid_<id>.
    EXPECT_EQ(parts.count("solid"), 0u) << "isolate " << isolate;
    for (const char* part : {"nut", "bolt", "rod", "plate", "l-bracket"}) {
      EXPECT_GT(parts[part], 0) << part << " (isolate " << isolate << ")";
    }
    int total = 0;
    for (const auto& [part, n] : parts) total += n;
    EXPECT_EQ(total, 18);
  }
}

TEST(CadNames, FaceColoursComeFromTheFile) {
  // CadQuery's red cube and blue cylinder: every face coloured.
  RDMESH_REQUIRE_SHARED_DATA(path, "step/cadquery_red_cube_blue_cylinder.step");
  for (const bool isolate : {true, false}) {
    const auto oracle = load(path, isolate);
    std::map<std::string, int> colors;
    for (const PatchInfo& p : oracle->patches()) ++colors[oracle->patch_color(p.id)];
    EXPECT_EQ(colors.count(""), 0u) << "a face without its colour (isolate " << isolate << ")";
    EXPECT_GT(colors["#dd5228"], 0) << "no red face";   // 0.8667 0.3216 0.1569
    EXPECT_GT(colors["#3b61b4"], 0) << "no blue face";  // 0.2314 0.3804 0.7059
  }
}

TEST(CadNames, OneBlueFaceOnAGreyBoxAndNoUselessFaceNames) {
  // Every face of this box is named "PartBody" (the body's name): no face name;
  // the faces are grey but for the blue ones.
  RDMESH_REQUIRE_SHARED_DATA(path, "step/gmsh_box_step_boundary_colors.stp");
  const auto oracle = load(path, true);
  std::map<std::string, int> colors;
  for (const PatchInfo& p : oracle->patches()) {
    EXPECT_EQ(p.name, "face_" + std::to_string(p.id.value));
    ++colors[oracle->patch_color(p.id)];
  }
  EXPECT_GT(colors["#0080ff"], 0) << "no blue face";
  EXPECT_GT(colors["#e1e1e1"], 0) << "no grey face";
  ASSERT_EQ(oracle->subdomains().size(), 1u);
  EXPECT_EQ(oracle->subdomains()[0].name, "PartBody");
}

TEST(CadNames, FilesWithoutNamesKeepTheNumberedOnes) {
  const auto box = make_cad_test_oracle(CadTestShape::two_boxes);
  for (const PatchInfo& p : box->patches()) {
    EXPECT_EQ(p.name, "face_" + std::to_string(p.id.value));
    EXPECT_EQ(box->patch_color(p.id), "");
  }
}

}  // namespace
}  // namespace rdmesh
