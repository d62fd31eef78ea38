// Reading CAD files in a child process (CadOptions::isolate): the same model as
// a read in this process, down to the last bit of the volume; a crash, a
// time-out of the child becomes an InputError, its memory limit holds; and
// the checks that stop OpenCASCADE's known endless loops at their cause.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "rdmesh/cad_oracle.h"
#include "rdmesh/errors.h"
#include "shared_data.h"

#if defined(__SANITIZE_ADDRESS__)
#define RDMESH_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RDMESH_TEST_ASAN 1
#endif
#endif

namespace rdmesh {
namespace {

namespace fs = std::filesystem;

CadOptions in_process() {
  CadOptions o;
  o.isolate = false;
  return o;
}

fs::path scratch() {
  const fs::path dir = fs::temp_directory_path() / "rdmesh_cad_isolated_read_test";
  fs::create_directories(dir);
  return dir;
}

// A test shape written as a BREP file in scratch(), and the file's text.
std::string brep_text(CadTestShape shape, const std::string& path) {
  write_cad_test_shape(shape, path);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The InputError's message, or "" when loading succeeds.
std::string load_error(const std::string& path, const CadOptions& options) {
  try {
    load_cad_file(path, options);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    return e.what();
  }
  return {};
}

TEST(CadIsolatedRead, GivesTheSameModelAsReadingInProcess) {
  // drill: cones whose axes the BREP formats would rebuild a bit differently;
  // nist_ctc_01: a named solid; cube and cylinder: two solids fused.
  for (const char* file : {"step/occtsample_drill.step", "step/nist_ctc_01_asme1_ap242-e1.stp",
                           "step/cadquery_red_cube_blue_cylinder.step"}) {
    SCOPED_TRACE(file);
    RDMESH_REQUIRE_SHARED_DATA(path, file);
    const auto here = load_cad_file(path, in_process());
    const auto child = load_cad_file(path);
    ASSERT_EQ(child->subdomains().size(), here->subdomains().size());
    for (std::size_t i = 0; i < here->subdomains().size(); ++i) {
      EXPECT_EQ(child->subdomains()[i].name, here->subdomains()[i].name);
    }
    EXPECT_EQ(child->patches().size(), here->patches().size());
    EXPECT_EQ(child->curves().size(), here->curves().size());
    EXPECT_EQ(child->corners().size(), here->corners().size());
    EXPECT_EQ(child->input_solids(), here->input_solids());
    EXPECT_EQ(child->log(), here->log());
    // Bit for bit: the geometry came back exactly.
    EXPECT_EQ(child->exact_volume(), here->exact_volume());
    EXPECT_EQ(child->tolerance(), here->tolerance());
  }
  RDMESH_REQUIRE_SHARED_DATA(named, "step/nist_ctc_01_asme1_ap242-e1.stp");
  EXPECT_EQ(load_cad_file(named)->subdomains().at(0).name, "PartBody");
}

TEST(CadIsolatedRead, ATimeOutIsAnInputError) {
  RDMESH_REQUIRE_SHARED_DATA(path, "step/gmsh_Kurbelwelle.stp");
  CadOptions options;
  options.read_time_limit = 0.001;  // reading this file takes a tenth of a second
  const std::string error = load_error(path, options);
  EXPECT_NE(error.find("the STEP reader did not finish within 0.001 s of computing"),
            std::string::npos)
      << error;
}

TEST(CadIsolatedRead, ACrashOfTheReaderIsAnInputError) {
  RDMESH_REQUIRE_SHARED_DATA(path, "bad/crash_missing_vector.stp");
  const std::string error = load_error(path, {});
  EXPECT_NE(error.find("the STEP reader crashed (malformed file?)"), std::string::npos) << error;
}

#ifndef RDMESH_TEST_ASAN  // no address-space limit under AddressSanitizer
TEST(CadIsolatedRead, TheMemoryLimitStopsARunawayAllocation) {
  // A BREP file whose first 3D curve claims a B-spline of 50 million poles:
  // the reader allocates and zeroes them (1.2 GB, a second) before it reads
  // any. Under the limit the allocation fails at once; OpenCASCADE's reader
  // catches that itself and reports a table it cannot parse.
  const std::string text = brep_text(CadTestShape::box, (scratch() / "box.brep").string());
  const std::string path = (scratch() / "many_poles.brep").string();
  std::ofstream(path) << std::regex_replace(text, std::regex("\nCurves ([0-9]+)\n[^\n]*\n"),
                                            "\nCurves $1\n7 0 0 1 50000000 2 0 0 0 1 0 0\n");
  CadOptions options;
  options.read_memory_limit_mib = 64;
  const std::string error = load_error(path, options);
  EXPECT_TRUE(error.find("cannot parse the BREP file") != std::string::npos ||
              error.find("the BREP reader ran out of memory") != std::string::npos)
      << error;
  // The reader's child is this test's only child (ctest runs each test in a
  // process of its own): its peak resident set, which includes what it shares
  // with this process, stays far below the 1.2 GB it asked for.
  rusage children{};
  ASSERT_EQ(getrusage(RUSAGE_CHILDREN, &children), 0);
  const double peak_mb = static_cast<double>(children.ru_maxrss) / 1024;  // KiB on Linux
  EXPECT_GT(peak_mb, 0.0) << "no child was reaped";
  EXPECT_LT(peak_mb, 600.0) << "the child seems to have had the 1.2 GB";
}
#endif

// The known endless loops, stopped before OpenCASCADE enters them (in process,
// so that the checks alone are tested).
TEST(CadIsolatedRead, NonFiniteStepNumbersAreRejectedBeforeTheTransfer) {
  RDMESH_REQUIRE_SHARED_DATA(point, "bad/hang_inf_point.stp");
  EXPECT_NE(load_error(point, in_process()).find("#91 (CARTESIAN_POINT) has a non-finite"),
            std::string::npos);
  RDMESH_REQUIRE_SHARED_DATA(direction, "bad/hang_inf_direction.stp");
  EXPECT_NE(load_error(direction, in_process()).find("#47 (DIRECTION) has a non-finite"),
            std::string::npos);
}

TEST(CadIsolatedRead, BrepSectionsLongerThanTheFileAreRejected) {
  const std::string good = (scratch() / "bmc.brep").string();
  const std::string text = brep_text(CadTestShape::box_minus_cylinder, good);
  EXPECT_EQ(load_error(good, in_process()), "");
  const std::string huge = (scratch() / "huge.brep").string();
  std::ofstream(huge) << std::regex_replace(text, std::regex("\nCurve2ds [0-9]+\n"),
                                            "\nCurve2ds 2000000000\n");
  EXPECT_NE(load_error(huge, in_process()).find("announces 2000000000 Curve2ds"),
            std::string::npos);
  const std::string cut = (scratch() / "cut.brep").string();
  std::ofstream(cut) << text.substr(0, text.size() * 3 / 4);
  EXPECT_NE(load_error(cut, in_process()).find("TShapes"), std::string::npos);
}

TEST(CadIsolatedRead, ADegenerateTorusIsRejectedAtLoad) {
  RDMESH_REQUIRE_SHARED_DATA(path, "bad/e3_torus_R0.stp");
  EXPECT_NE(load_error(path, in_process()).find("degenerate surface (a torus of major radius 0"),
            std::string::npos);
}

}  // namespace
}  // namespace rdmesh
