// The real inputs the tests mesh (STEP parts, triangle meshes), which nobody on
// the team wrote and which are never modified: see MANIFEST.md in that folder.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

namespace rdmesh::test {

/// The data folder: $RDMESH_DATA_DIR, else ../shared/data beside the checkout,
/// else /work/shared/data; empty when none of them exists.
inline std::string shared_data_dir() {
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("RDMESH_DATA_DIR"); env != nullptr && fs::is_directory(env)) {
    return env;
  }
  for (const fs::path dir : {fs::path(RDMESH_SOURCE_DIR) / ".." / "shared" / "data",
                             fs::path("/work/shared/data")}) {
    if (fs::is_directory(dir)) return dir.lexically_normal().string();
  }
  return {};
}

/// The path of `relative` (e.g. "mesh/cgal_fandisk.off") in the data folder,
/// or an empty string when the folder or the file is absent.
inline std::string shared_data(const std::string& relative) {
  const std::string dir = shared_data_dir();
  if (dir.empty()) return {};
  const std::filesystem::path p = std::filesystem::path(dir) / relative;
  return std::filesystem::exists(p) ? p.string() : std::string();
}

}  // namespace rdmesh::test

/// Declares `var` as the path of a shared data file, or skips the test.
#define RDMESH_SHARED_DATA_OR_SKIP(var, relative)                                   \
  const std::string var = ::rdmesh::test::shared_data(relative);                   \
  if (var.empty()) GTEST_SKIP() << "shared data file " << (relative) << " is absent"
