// SHA-256 against the FIPS 180-4 examples and against sha256sum on a file.
#include "rdmesh/sha256.h"

#include <gtest/gtest.h>

#include <string>

#include "io/io_test_util.h"
#include "rdmesh/errors.h"

namespace rdmesh::testing {
namespace {

std::string digest(const std::string& bytes) {
  Sha256 h;
  h.update(bytes);
  return h.hex_digest();
}

TEST(Sha256, MatchesTheStandardsExamples) {
  EXPECT_EQ(digest(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(digest("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(digest("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(digest(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, PiecesHashLikeTheWhole) {
  std::string text;
  for (int i = 0; i < 3000; ++i) text += static_cast<char>(i * 7 + 3);
  for (std::size_t cut : {0u, 1u, 55u, 56u, 63u, 64u, 65u, 1000u}) {
    Sha256 h;
    h.update(std::string_view(text).substr(0, cut));
    h.update(std::string_view(text).substr(cut));
    EXPECT_EQ(h.hex_digest(), digest(text)) << "cut at " << cut;
  }
}

TEST(Sha256, OfAFileIsWhatSha256sumSays) {
  TempDir dir;
  std::string bytes;
  for (int i = 0; i < 200000; ++i) bytes += static_cast<char>((i * 2654435761u) >> 24);
  write_text(dir.file("data.bin"), bytes);
  const auto r = run_command("sha256sum " + dir.file("data.bin"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(sha256_of_file(dir.file("data.bin")), r.output.substr(0, 64));
  EXPECT_THROW(sha256_of_file(dir.file("missing.bin")), InputError);
}

}  // namespace
}  // namespace rdmesh::testing
