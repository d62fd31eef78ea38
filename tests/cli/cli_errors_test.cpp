// Bad input: one line naming the file and the problem, exit code 2, no output file.
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_runner.h"

namespace rdmesh::test {
namespace {

const char* kSphere =
    R"({"bbox": [-1.2,-1.2,-1.2,1.2,1.2,1.2], "functions": {"s": "x^2+y^2+z^2-1"}})";

struct BadInput {
  const char* name;
  const char* file_text;   ///< written to in.json; nullptr: no file
  const char* extra_args;  ///< after "in.json -o out.msh"
  const char* expected;    ///< substring of the message
};

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, FailsWithOneLineExitTwoAndNoOutput) {
  const BadInput& c = GetParam();
  ScratchDir dir;
  if (c.file_text) dir.write("in.json", c.file_text);
  const std::string extra = c.extra_args;
  const std::string output = extra.rfind("-o ", 0) == 0 ? "" : "-o out.msh ";
  const CliRun run = run_cli("in.json --quiet " + output + extra, dir.path());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
  EXPECT_NE(run.output.find("rdmesh: error: "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find(c.expected), std::string::npos)
      << "message lacks '" << c.expected << "': " << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.msh")));
  EXPECT_EQ(dir.entries(), c.file_text ? 1u : 0u) << "a stray file was left behind";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliBadInput,
    ::testing::Values(
        BadInput{"missing_file", nullptr, "", "in.json"},
        BadInput{"malformed_json", R"({"bbox": [0,0,0,1,1,1], )", "", "in.json"},
        BadInput{"unknown_key",
                 R"({"bbox": [-1,-1,-1,1,1,1], "functions": {"s": "x"}, "colour": 3})", "",
                 "colour"},
        BadInput{"syntax_error", R"({"bbox": [-1,-1,-1,1,1,1], "functions": {"s": "x^2 + * y"}})",
                 "", "in.json"},
        BadInput{"unknown_variable",
                 R"({"bbox": [-1,-1,-1,1,1,1], "functions": {"s": "x^2 + w - 1"}})", "", "w"},
        BadInput{"empty_subdomain",
                 R"({"bbox": [-1,-1,-1,1,1,1], "functions": {"s": "x^2+y^2+z^2+1"}})", "",
                 "matches no point"},
        BadInput{
            "negative_size_in_file",
            R"({"bbox": [-1.2,-1.2,-1.2,1.2,1.2,1.2], "functions": {"s": "x^2+y^2+z^2-1"}, "size": -0.1})",
            "", "size"},
        BadInput{"negative_size_option", kSphere, "--size -0.1", "size"},
        BadInput{"nan_size_option", kSphere, "--size nan", "size"},
        BadInput{"zero_facet_distance", kSphere, "--facet-distance 0", "facet distance"},
        BadInput{"unwritable_output", kSphere, "-o missing_dir/out.msh", "missing_dir"},
        BadInput{"unknown_output_extension", kSphere, "-o out.xyz", "out.xyz"},
        BadInput{"unwritable_report", kSphere, "--report missing_dir/r.json", "missing_dir"},
        BadInput{"not_a_number", kSphere, "--size abc", "size"}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return info.param.name; });

TEST(CliBadInput, UnknownInputExtensionIsNamed) {
  ScratchDir dir;
  dir.write("part.xyz", "1 2 3");
  const CliRun run = run_cli("part.xyz -o out.msh", dir.path());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("part.xyz"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.msh")));
}

}  // namespace
}  // namespace rdmesh::test
