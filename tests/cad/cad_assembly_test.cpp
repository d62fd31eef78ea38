// Models as real files store them: solids without volume, solids inside out,
// solids inside other solids, slender parts. The model must still give every
// subdomain a non-negative volume and account for the whole of the input's
// volume, and say how thick its slender parts are (the default sizes follow it).
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "rdmesh/cad_oracle.h"
#include "shared_data.h"

namespace rdmesh {
namespace {

TEST(CadAssembly, ASolidWithoutVolumeIsLeftOutOfTheFuse) {
  // occt_Axis_of_bearing.brep: 18 solids, the 15th without volume. In the
  // general fuse it took the space around the others (volume -35673), the
  // 16th-18th got nothing, and refinement ran for ever on the wrong domain.
  RDMESH_REQUIRE_SHARED_DATA(path, "brep/occt_Axis_of_bearing.brep");
  const auto oracle = load_cad_file(path);
  ASSERT_EQ(oracle->subdomains().size(), 18u);
  double sum = 0;
  for (const SubdomainInfo& s : oracle->subdomains()) {
    const double v = oracle->exact_volume(s.id);
    EXPECT_GE(v, 0) << "subdomain " << s.id.value;
    sum += v;
  }
  // The housing, the shaft, twelve balls of radius 2 and three rings.
  // BRepGProp's volumes of the file's solids; the fuse takes shapes within a
  // millionth of the model's size (1.4e-4) as touching, which moves the
  // faces of solid 1 that the balls touch by as much (its volume by 0.16).
  EXPECT_NEAR(oracle->exact_volume(SubdomainId(1)), 29206.34, 0.2);
  EXPECT_NEAR(oracle->exact_volume(SubdomainId(3)), 4.0 / 3.0 * 3.14159265358979 * 8, 1e-6);
  EXPECT_NEAR(oracle->exact_volume(SubdomainId(16)), 8566.68, 0.01);
  EXPECT_EQ(oracle->exact_volume(SubdomainId(15)), 0);
  EXPECT_NEAR(sum, oracle->exact_volume(), 1e-9 * sum);
  ASSERT_EQ(oracle->warnings().size(), 1u);
  EXPECT_NE(oracle->warnings()[0].find("solid 15"), std::string::npos) << oracle->warnings()[0];
  EXPECT_NE(oracle->warnings()[0].find("no volume"), std::string::npos) << oracle->warnings()[0];
}

TEST(CadAssembly, PartsAHairApartAreFusedAsTouching) {
  // occtdata_as1_motor.step: 35 solids in a 300,000-unit assembly, parts placed
  // 0.01 apart or 0.01 into each other. The exact fuse cut faces 0.01 wide along
  // whole circles (areas 18 to 975 along curves 80,000 to 100,000 long): the
  // curves on either side of such a face got 2 x 3,663 protecting balls, 17,886
  // pairs of them could not be separated, and the run was still refining after
  // 150 s. Shapes within a millionth of the model's size are fused as touching.
  RDMESH_REQUIRE_SHARED_DATA(path, "step/occtdata_as1_motor.step");
  const auto oracle = load_cad_file(path);
  ASSERT_EQ(oracle->subdomains().size(), 35u);
  const double diagonal = oracle->bounding_box().diagonal();
  for (const PatchInfo& p : oracle->patches()) {
    EXPECT_GT(oracle->exact_area(p.id), 1e-7 * diagonal * diagonal) << "patch " << p.id.value;
  }
  // Parts that touch no other keep their volume (BRepGProp of the file's solids).
  EXPECT_NEAR(oracle->exact_volume(SubdomainId(3)), 5.424e13, 1e-9 * 5.424e13);
  EXPECT_NEAR(oracle->exact_volume(SubdomainId(2)), 552912556185.85, 1.0);
  double sum = 0;
  for (const SubdomainInfo& s : oracle->subdomains()) {
    const double v = oracle->exact_volume(s.id);
    EXPECT_GE(v, 0) << "subdomain " << s.id.value;
    sum += v;
  }
  EXPECT_NEAR(sum, oracle->exact_volume(), 1e-9 * sum);
}

TEST(CadThickness, ARodIsAsThickAsItsDiameterAndAHoleIsNotSlender) {
  // A solid cylinder of radius 5: its side bends towards the material with a
  // radius half the material's thickness (10).
  const auto rod = make_cad_test_oracle(CadTestShape::cylinder);
  int curved = 0;
  for (const PatchInfo& p : rod->patches()) {
    const std::optional<double> t = rod->curved_thickness(p.id);
    if (!t) continue;
    ++curved;
    EXPECT_NEAR(*t, 10, 1e-3) << "patch " << p.id.value;
  }
  EXPECT_EQ(curved, 1);  // the side; the planar caps have none
  // A box with a hole of radius 4: the hole's wall bends away from the material.
  const auto holed = make_cad_test_oracle(CadTestShape::box_minus_cylinder);
  for (const PatchInfo& p : holed->patches()) {
    EXPECT_FALSE(holed->curved_thickness(p.id)) << "patch " << p.id.value;
  }
  // A ball of radius 10 is as thick as its diameter.
  const auto ball = make_cad_test_oracle(CadTestShape::sphere);
  ASSERT_EQ(ball->patches().size(), 1u);
  const std::optional<double> t = ball->curved_thickness(PatchId(1));
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 20, 1e-3);
}

}  // namespace
}  // namespace rdmesh
