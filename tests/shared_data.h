// The real inputs the tests mesh (STEP parts, triangle meshes), which nobody on
// the team wrote and which are never modified: see MANIFEST.md in that folder.
//
// The folder is $RDMESH_DATA_DIR, else ../shared/data beside the checkout.
// When it (or a file in it) is missing, a test that needs it is skipped with a
// message on a developer's machine, and FAILS when the environment variable CI
// is set (to anything but "" or "0"): a test that skips in CI hides exactly
// the failures CI exists for.
#pragma once

#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace rdmesh::test {

/// The data folder: $RDMESH_DATA_DIR, else ../shared/data beside the checkout;
/// empty when neither exists.
inline std::string shared_data_dir() {
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("RDMESH_DATA_DIR"); env != nullptr && fs::is_directory(env)) {
    return env;
  }
  const fs::path beside = fs::path(RDMESH_SOURCE_DIR) / ".." / "shared" / "data";
  if (fs::is_directory(beside)) return beside.lexically_normal().string();
  return {};
}

/// The path of `relative` (e.g. "mesh/cgal_fandisk.off") in the data folder,
/// or an empty string when the folder or the file is absent.
inline std::string shared_data(const std::string& relative) {
  const std::string dir = shared_data_dir();
  if (dir.empty()) return {};
  const std::filesystem::path p = std::filesystem::path(dir) / relative;
  return std::filesystem::exists(p) ? p.lexically_normal().string() : std::string();
}

/// A test name for a data file of a parameterized test: its name up to the
/// first '.', other characters than letters and digits as '_'.
inline std::string file_test_name(const std::string& file) {
  std::string n = file.substr(0, file.find('.'));
  for (char& ch : n) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return n;
}

/// True when missing data must fail a test rather than skip it ($CI is set).
inline bool shared_data_required() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && *ci != '\0' && std::string(ci) != "0";
}

/// Records that a test's prerequisite (shared data, a tool such as gmsh) is
/// missing: a failure under CI, else a skip. The caller returns right after.
inline void report_missing_prerequisite(const std::string& what) {
  if (shared_data_required()) {
    ADD_FAILURE() << what << " is absent; CI is set, so this is a failure, not a skip";
  } else {
    GTEST_SKIP() << what << " is absent";
  }
}

}  // namespace rdmesh::test

/// Ends the current test because a prerequisite `what` is missing (fails under CI).
#define RDMESH_MISSING_PREREQUISITE(what) return ::rdmesh::test::report_missing_prerequisite(what)

/// Ends the current test because shared data `what` is missing (fails under CI).
#define RDMESH_MISSING_SHARED_DATA(what)                           \
  RDMESH_MISSING_PREREQUISITE("shared data " + std::string(what) + \
                              " (in $RDMESH_DATA_DIR or " RDMESH_SOURCE_DIR "/../shared/data)")

/// Declares `var` as the path of a shared data file, or ends the test (a
/// failure under CI, a skip elsewhere) when the file is absent.
#define RDMESH_REQUIRE_SHARED_DATA(var, relative)                \
  const std::string var = ::rdmesh::test::shared_data(relative); \
  if (var.empty()) RDMESH_MISSING_SHARED_DATA(relative)
