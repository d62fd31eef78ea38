// Sizes per entity on shared STEP parts: a face asked at a quarter of the
// default size gets edges about that long (at most twice the asked ball
// radius on average) and several times more of them, by id and by name.
#include <gtest/gtest.h>

#include <cstdio>

#include "rdmesh/cad_oracle.h"
#include "rdmesh/entity_sizes.h"
#include "rdmesh/mesher.h"
#include "shared_data.h"

namespace rdmesh {
namespace {

class EntitySizesCad : public ::testing::TestWithParam<const char*> {};

TEST_P(EntitySizesCad, AFaceGetsTheSizeAsked) {
  const std::string path = test::shared_data(std::string("step/") + GetParam());
  if (path.empty()) RDMESH_MISSING_SHARED_DATA(std::string("step/") + GetParam());
  const auto oracle = load_cad_file(path);
  const Criteria base = default_criteria(oracle->bounding_box());
  // The largest face, named as in the .msh physical groups.
  PatchInfo largest = oracle->patches().front();
  for (const PatchInfo& p : oracle->patches()) {
    if (oracle->exact_area(p.id) > oracle->exact_area(largest.id)) largest = p;
  }
  const double h = 0.25 * base.facet_size(oracle->bounding_box().center());
  const std::vector<EntitySize> asked{
      parse_entity_size("face:" + largest.name + "=" + std::to_string(h), *oracle)};
  ASSERT_EQ(asked[0].id, largest.id.value);
  Criteria c = base;
  apply_entity_sizes(*oracle, asked, 1.4, c);
  const AchievedSize before = achieved_sizes(generate_mesh(*oracle, base).mesh, asked)[0];
  const AchievedSize after = achieved_sizes(generate_mesh(*oracle, c).mesh, asked)[0];
  std::printf("%s face %s: asked %.3g, edges %zu -> %zu, mean %.3g -> %.3g, max %.3g -> %.3g\n",
              GetParam(), largest.name.c_str(), h, before.edges, after.edges, before.mean_edge,
              after.mean_edge, before.max_edge, after.max_edge);
  EXPECT_LE(after.mean_edge, 2 * h);
  EXPECT_GT(after.edges, 4 * before.edges);
}

INSTANTIATE_TEST_SUITE_P(Parts, EntitySizesCad,
                         ::testing::Values("cadquery_red_cube_blue_cylinder.step",
                                           "occtsample_MBBGehauseRohteil.step"),
                         [](const auto& info) { return test::file_test_name(info.param); });

}  // namespace
}  // namespace rdmesh
