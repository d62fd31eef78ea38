// CAD files: STEP / BREP / IGES round trips of OpenCASCADE-built models, the
// shipped data files, and clear InputErrors for bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "rdmesh/cad_oracle.h"
#include "rdmesh/errors.h"
#include "shared_data.h"

namespace rdmesh {
namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  const fs::path dir = fs::temp_directory_path() / "rdmesh_cad_files_test";
  fs::create_directories(dir);
  return dir;
}

struct RoundTrip {
  CadTestShape shape;
  const char* file;
};

class CadRoundTrip : public ::testing::TestWithParam<RoundTrip> {};

TEST_P(CadRoundTrip, ReadsBackTheSameModel) {
  const RoundTrip& r = GetParam();
  const auto direct = make_cad_test_oracle(r.shape);
  const std::string path = (scratch() / r.file).string();
  write_cad_test_shape(r.shape, path);
  const auto read = load_cad_file(path);
  EXPECT_EQ(read->subdomains().size(), direct->subdomains().size());
  EXPECT_EQ(read->patches().size(), direct->patches().size());
  EXPECT_EQ(read->curves().size(), direct->curves().size());
  EXPECT_EQ(read->corners().size(), direct->corners().size());
  EXPECT_NEAR(read->exact_volume(), direct->exact_volume(), 1e-6 * direct->exact_volume());
}

INSTANTIATE_TEST_SUITE_P(Formats, CadRoundTrip,
                         ::testing::Values(RoundTrip{CadTestShape::box_minus_cylinder, "bmc.step"},
                                           RoundTrip{CadTestShape::two_boxes, "two_boxes.stp"},
                                           RoundTrip{CadTestShape::cylinder, "cylinder.brep"},
                                           RoundTrip{CadTestShape::sphere, "sphere.brep"},
                                           RoundTrip{CadTestShape::box, "box.igs"}),
                         [](const auto& info) {
                           std::string n = info.param.file;
                           for (char& ch : n)
                             ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                           return n;
                         });

void expect_input_error(const std::string& path, const std::string& fragment) {
  try {
    load_cad_file(path);
    ADD_FAILURE() << path << ": no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(CadFiles, BadInputIsAnInputError) {
  const fs::path dir = scratch();
  expect_input_error((dir / "missing.step").string(), "no such file");
  std::ofstream(dir / "empty.step").close();
  expect_input_error((dir / "empty.step").string(), "empty");
  std::ofstream(dir / "garbage.step") << "ISO-10303-21;\nthis is not STEP\n";
  expect_input_error((dir / "garbage.step").string(), "STEP");
  std::ofstream(dir / "garbage.brep") << "not a brep\n";
  expect_input_error((dir / "garbage.brep").string(), "BREP");
  std::ofstream(dir / "garbage.igs") << "not an iges file\n";
  expect_input_error((dir / "garbage.igs").string(), "IGES");
  // A truncated STEP file: the first half of a valid one.
  write_cad_test_shape(CadTestShape::box_minus_cylinder, (dir / "full.step").string());
  std::ifstream in(dir / "full.step");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir / "truncated.step") << text.substr(0, text.size() / 2);
  expect_input_error((dir / "truncated.step").string(), "");
}

TEST(CadFiles, ReadsTheSharedStepAndBrepFiles) {
  struct Expected {
    const char* file;
    int solids, faces;
  };
  for (const Expected& e : {Expected{"step/gmsh_box_step_boundary_colors.stp", 1, 6},
                            Expected{"step/gmsh_torus_step_header_data.stp", 1, 1},
                            Expected{"step/cadquery_red_cube_blue_cylinder.step", 2, 9},
                            Expected{"brep/occt_bottle.brep", 1, -1}}) {
    SCOPED_TRACE(e.file);
    RDMESH_REQUIRE_SHARED_DATA(path, e.file);
    const auto o = load_cad_file(path);
    EXPECT_EQ(static_cast<int>(o->subdomains().size()), e.solids);
    if (e.faces > 0) {
      EXPECT_EQ(static_cast<int>(o->patches().size()), e.faces);
    }
    EXPECT_GT(o->exact_volume(), 0);
  }
}

}  // namespace
}  // namespace rdmesh
