// write_file_atomically: files larger than the write-behind step come out
// byte for byte, and a write the kernel refuses is an OutputError that leaves
// the previous file and no temporary.
#include "rdmesh/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <string>

#include "io/io_test_util.h"
#include "rdmesh/errors.h"

namespace rdmesh {
namespace {

using testing::TempDir;

/// Numbers as text, about `bytes` long, never the same line twice.
std::string numbered_lines(std::size_t bytes) {
  std::string text;
  for (std::size_t i = 0; text.size() < bytes; ++i) text += std::to_string(i * 7919) + " x\n";
  return text;
}

TEST(AtomicFile, ALargeFileIsWrittenByteForByteInPiecesOfAnySize) {
  TempDir dir;
  const std::string path = dir.file("large.txt");
  // Over four write-behind steps, written in pieces that straddle the buffer.
  const std::string text = numbered_lines(std::size_t{17} << 20);
  write_file_atomically(path, [&](std::ostream& out) {
    for (std::size_t at = 0; at < text.size(); at += 99991) out << text.substr(at, 99991);
    out.put('!');
  });
  EXPECT_EQ(testing::read_text(path), text + "!");
  EXPECT_EQ(std::filesystem::file_size(path), text.size() + 1);
}

/// Limits the size of files this process writes while alive (RLIMIT_FSIZE,
/// SIGXFSZ ignored: write() then fails with EFBIG), as a full disk would.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    previous_signal_ = std::signal(SIGXFSZ, SIG_IGN);
    ::getrlimit(RLIMIT_FSIZE, &previous_);
    rlimit limited = previous_;
    limited.rlim_cur = bytes;
    ok_ = ::setrlimit(RLIMIT_FSIZE, &limited) == 0;
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &previous_);
    std::signal(SIGXFSZ, previous_signal_);
  }
  bool ok() const { return ok_; }

 private:
  rlimit previous_{};
  void (*previous_signal_)(int) = nullptr;
  bool ok_ = false;
};

TEST(AtomicFile, AWriteTheKernelRefusesIsAnOutputErrorAndLeavesThePreviousFile) {
  TempDir dir;
  const std::string path = dir.file("out.mesh");
  testing::write_text(path, "previous\n");
  const std::string text = numbered_lines(std::size_t{6} << 20);
  {
    const FileSizeLimit limit(std::size_t{1} << 20);
    ASSERT_TRUE(limit.ok());
    try {
      write_file_atomically(path, [&](std::ostream& out) { out << text; });
      FAIL() << "a write past the file size limit succeeded";
    } catch (const OutputError& e) {
      EXPECT_NE(std::string(e.what()).find("write failed"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(testing::read_text(path), "previous\n");
  std::size_t entries = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) {
    EXPECT_EQ(e.path().filename(), "out.mesh");
    ++entries;
  }
  EXPECT_EQ(entries, 1u);
}

}  // namespace
}  // namespace rdmesh
