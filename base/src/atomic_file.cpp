// Atomic file write: temp file (O_EXCL) in the target directory, written
// behind as it goes, fsync, rename.
#include "rdmesh/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <ostream>
#include <random>
#include <streambuf>
#include <system_error>
#include <utility>
#include <vector>

#include "rdmesh/errors.h"

namespace rdmesh {
namespace {

namespace fs = std::filesystem;

std::string errno_message(int err) {
  return std::error_code(err, std::generic_category()).message();
}

/// Creates a new, empty file "path.tmp-XXXXXX" (O_EXCL, so never someone
/// else's file) and returns its name.
std::string create_temp_file(const std::string& path) {
  static constexpr char kAlphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  std::random_device seed;
  std::mt19937 random(seed());
  std::uniform_int_distribution<int> pick(0, sizeof kAlphabet - 2);
  int last_error = 0;
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string name = path + ".tmp-";
    for (int i = 0; i < 6; ++i) name += kAlphabet[pick(random)];
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return name;
    }
    last_error = errno;
    if (last_error != EEXIST) break;
  }
  const fs::path dir = fs::path(path).parent_path();
  throw OutputError(path + ": cannot create a file in directory '" +
                    (dir.empty() ? std::string(".") : dir.string()) + "' (" +
                    errno_message(last_error) + ")");
}

/// An output stream buffer over a file descriptor that asks the kernel to
/// start writing each kWriteBehind bytes to disk as soon as they are written
/// (sync_file_range), so that the fsync before the rename finds little left to
/// do: for a 45 MB mesh the fsync alone took 0.14 s, at the end of the run.
class WriteBehindBuf : public std::streambuf {
 public:
  static constexpr std::size_t kWriteBehind = std::size_t{4} << 20;

  explicit WriteBehindBuf(int fd) : fd_(fd), buffer_(1 << 16) {
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }
  WriteBehindBuf(const WriteBehindBuf&) = delete;
  WriteBehindBuf& operator=(const WriteBehindBuf&) = delete;

  bool failed() const { return failed_; }

 protected:
  int_type overflow(int_type ch) override {
    if (!drain()) return traits_type::eof();
    if (traits_type::eq_int_type(ch, traits_type::eof())) return traits_type::not_eof(ch);
    *pptr() = traits_type::to_char_type(ch);
    pbump(1);
    return ch;
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  /// Writes the buffer out; false (and failed()) on an error.
  bool drain() {
    const char* p = pbase();
    while (p < pptr() && !failed_) {
      const ssize_t n = ::write(fd_, p, static_cast<std::size_t>(pptr() - p));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        failed_ = true;
        break;
      }
      p += n;
      written_ += static_cast<std::size_t>(n);
    }
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    if (!failed_ && written_ - started_ >= kWriteBehind) {
      // Only a hint: where the kernel cannot, the fsync does it all.
      (void)::sync_file_range(fd_, static_cast<off_t>(started_),
                              static_cast<off_t>(written_ - started_), SYNC_FILE_RANGE_WRITE);
      started_ = written_;
    }
    return !failed_;
  }

  int fd_;
  std::vector<char> buffer_;
  std::size_t written_ = 0;  ///< bytes handed to the kernel
  std::size_t started_ = 0;  ///< bytes whose write-back was asked for
  bool failed_ = false;
};

/// Writes the file with `writer` and flushes its data to disk, so that the
/// rename never exposes an empty file after a crash.
void write_temp(const std::string& temp, const std::string& path,
                const std::function<void(std::ostream&)>& writer) {
  const int fd = ::open(temp.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) {
    throw OutputError(path + ": cannot open temporary file " + temp + " (" + errno_message(errno) +
                      ")");
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  WriteBehindBuf buffer(fd);
  std::ostream out(&buffer);
  try {
    writer(out);
  } catch (const OutputError&) {
    throw OutputError(path + ": write failed (disk full or I/O error?)");
  }
  out.flush();
  if (!out || buffer.failed()) throw OutputError(path + ": write failed (disk full or I/O error?)");
  if (::fsync(fd) != 0) {
    throw OutputError(path + ": cannot sync the written data (" + errno_message(errno) + ")");
  }
}

}  // namespace

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& writer) {
  StagedFile(path, writer).commit();
}

StagedFile::StagedFile(const std::string& path, const std::function<void(std::ostream&)>& writer)
    : path_(path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw OutputError(path + ": is a directory");
  temp_ = create_temp_file(path);
  try {
    write_temp(temp_, path, writer);
  } catch (...) {
    discard();
    throw;
  }
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : path_(std::move(other.path_)), temp_(std::exchange(other.temp_, std::string())) {}

StagedFile& StagedFile::operator=(StagedFile&& other) noexcept {
  if (this != &other) {
    discard();
    path_ = std::move(other.path_);
    temp_ = std::exchange(other.temp_, std::string());
  }
  return *this;
}

StagedFile::~StagedFile() { discard(); }

void StagedFile::commit() {
  if (temp_.empty()) throw InternalError(path_ + ": StagedFile committed twice or after a move");
  std::error_code ec;
  fs::rename(temp_, path_, ec);
  if (ec) {
    discard();
    throw OutputError(path_ + ": cannot replace the file (" + ec.message() + ")");
  }
  temp_.clear();
}

void StagedFile::discard() noexcept {
  if (temp_.empty()) return;
  std::error_code ec;
  fs::remove(temp_, ec);
  temp_.clear();
}

}  // namespace rdmesh
