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
  EXPECT_NEAR(oracle->exact_volume(SubdomainId(1)), 29206.34, 0.01);
  EXPECT_NEAR(oracle->exact_volume(SubdomainId(3)), 4.0 / 3.0 * 3.14159265358979 * 8, 1e-6);
  EXPECT_NEAR(oracle->exact_volume(SubdomainId(16)), 8566.68, 0.01);
  EXPECT_EQ(oracle->exact_volume(SubdomainId(15)), 0);
  EXPECT_NEAR(sum, oracle->exact_volume(), 1e-9 * sum);
  ASSERT_EQ(oracle->warnings().size(), 1u);
  EXPECT_NE(oracle->warnings()[0].find("solid 15"), std::string::npos) << oracle->warnings()[0];
  EXPECT_NE(oracle->warnings()[0].find("no volume"), std::string::npos) << oracle->warnings()[0];
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
