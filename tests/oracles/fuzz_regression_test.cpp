// Inputs found by fuzzing (scripts/fuzz.sh), minimised and kept: every file of
// fuzz_regressions/TARGET/ goes through the same reader as the fuzz target
// TARGET (fuzz/fuzz_inputs.h) and must either load or throw InputError.
//
// fuzz_regressions/open/TARGET/ is for findings not fixed yet (not run here:
// under the sanitizers they abort the whole test program); move a file into
// TARGET/ with its fix. ply/nan_list_length.ply came from there: a binary PLY
// list whose count type is float and whose count is NaN, which the reader
// cast to long long before checking it (UBSan; 1e30 did the same).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "../../fuzz/fuzz_inputs.h"
#include "rdmesh/errors.h"

namespace {

namespace fs = std::filesystem;

const fs::path kRegressions = fs::path(RDMESH_SOURCE_DIR) / "tests/oracles/fuzz_regressions";

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(FuzzRegressions, EveryInputLoadsOrIsAnInputError) {
  int files = 0;
  for (std::string_view target : rdmesh::fuzz::kTargets) {
    const fs::path folder = kRegressions / target;
    if (!fs::is_directory(folder)) continue;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
      SCOPED_TRACE(entry.path().string());
      ++files;
      const std::string bytes = read_bytes(entry.path());
      try {
        rdmesh::fuzz::read_input(target, bytes);
      } catch (const rdmesh::InputError&) {
      } catch (const std::exception& e) {
        ADD_FAILURE() << "not an InputError: " << e.what();
      }
    }
  }
  EXPECT_GT(files, 0) << "no regression input found in " << kRegressions;
}

TEST(FuzzRegressions, EveryFolderIsATarget) {
  for (const fs::directory_entry& entry : fs::directory_iterator(kRegressions)) {
    const std::string name = entry.path().filename().string();
    if (name == "open") continue;
    EXPECT_NE(std::find(std::begin(rdmesh::fuzz::kTargets), std::end(rdmesh::fuzz::kTargets), name),
              std::end(rdmesh::fuzz::kTargets))
        << name << " is not a fuzz target: its inputs would never be read";
  }
}

}  // namespace
