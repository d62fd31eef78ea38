// PLY headers whose counts the body cannot hold are refused before anything is
// read or allocated (issue 23: a 10^12-vertex header in a tiny file ran out of
// memory, an element without properties and a huge count never ended).
#include <gtest/gtest.h>

#include <cmath>
#include <ctime>
#include <sstream>
#include <string>

#include "rdmesh/errors.h"
#include "rdmesh/triangle_mesh_io.h"

namespace rdmesh {
namespace {

constexpr const char* kTriangle =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n3 0 1 2";  // no final newline

/// The InputError message of parsing `text`, or "" when it parses; fails the test
/// when parsing takes more than a CPU-second.
std::string ply_error(const std::string& text) {
  std::istringstream in(text);
  const std::clock_t start = std::clock();  // CPU time: a loaded machine does not stretch it
  std::string message;
  try {
    parse_ply(in, "t.ply");
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_LT(double(std::clock() - start) / CLOCKS_PER_SEC, 1.0);
  return message;
}

TEST(PlyLimits, ValidFileWithoutFinalNewlineAndEmptyExtraElementLoads) {
  std::string text = kTriangle;
  text.insert(text.find("end_header"), "element junk 0\n");
  std::istringstream in(text);
  const TriangleSoup soup = parse_ply(in, "t.ply");
  EXPECT_EQ(soup.points.size(), 3u);
  EXPECT_EQ(soup.triangles.size(), 1u);
}

TEST(PlyLimits, ElementWithoutPropertiesIsRefused) {
  std::string text = kTriangle;
  text.insert(text.find("end_header"), "element junk 9000000000000000000\n");
  const std::string e = ply_error(text);
  EXPECT_NE(e.find("t.ply: "), std::string::npos) << e;
  EXPECT_NE(e.find("'junk'"), std::string::npos) << e;
  EXPECT_NE(e.find("no property"), std::string::npos) << e;
}

TEST(PlyLimits, CountsBeyondTheFileSizeAreRefusedBeforeReading) {
  for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    const std::string text = std::string("ply\nformat ") + format +
                             " 1.0\nelement vertex 1000000000000\nproperty float x\n"
                             "property float y\nproperty float z\nend_header\n0 0 0\n";
    const std::string e = ply_error(text);
    EXPECT_NE(e.find("1000000000000 'vertex' items"), std::string::npos) << format << ": " << e;
    EXPECT_NE(e.find("ends early"), std::string::npos) << format << ": " << e;
  }
}

TEST(PlyLimits, FaceCountBeyondTheFileSizeIsRefused) {
  std::string text = kTriangle;
  text.replace(text.find("element face 1"), 14, "element face 4000000000");
  EXPECT_NE(ply_error(text).find("4000000000 'face' items"), std::string::npos);
}

TEST(PlyLimits, NonFiniteOrHugeListCountsAndIndicesAreRefusedBeforeAnyCast) {
  // A binary face list whose count is a float: NaN or 1e30 was cast to long
  // long before the check (undefined behaviour, found by fuzzing); an index of
  // 1e30 likewise. The body is long enough for the header's counts.
  auto binary = [](float count, float index) {
    std::string text =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list float float vertex_indices\nend_header\n";
    const float values[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, count, 0, 1, index};
    text.append(reinterpret_cast<const char*>(values), sizeof values);
    text.append(64, '\0');
    return text;
  };
  EXPECT_EQ(ply_error(binary(3, 2)), "");
  for (const float count : {std::nanf(""), 1e30f, -1.0f, 2.5f}) {
    const std::string e = ply_error(binary(count, 2));
    EXPECT_NE(e.find("bad list length"), std::string::npos) << count << ": " << e;
  }
  const std::string e = ply_error(binary(3, 1e30f));
  EXPECT_NE(e.find("bad vertex index"), std::string::npos) << e;
}

}  // namespace
}  // namespace rdmesh
