// Atomic file write: temp file (O_EXCL) in the target directory, fsync, rename.
#include "rdmesh/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <random>
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

/// Flushes the file's data to disk so that the rename never exposes an empty file after a crash.
void sync_file(const std::string& name, const std::string& path) {
  const int fd = ::open(name.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    const int err = errno;
    if (fd >= 0) ::close(fd);
    throw OutputError(path + ": cannot sync the written data (" + errno_message(err) + ")");
  }
  ::close(fd);
}

void write_temp(const std::string& temp, const std::string& path,
                const std::function<void(std::ostream&)>& writer) {
  std::ofstream out(temp, std::ios::binary | std::ios::trunc);
  if (!out) throw OutputError(path + ": cannot open temporary file " + temp);
  std::vector<char> buffer(1 << 16);
  out.rdbuf()->pubsetbuf(buffer.data(), static_cast<std::streamsize>(buffer.size()));
  try {
    writer(out);
  } catch (const OutputError&) {
    throw OutputError(path + ": write failed (disk full or I/O error?)");
  }
  out.close();
  if (!out) throw OutputError(path + ": write failed (disk full or I/O error?)");
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
    sync_file(temp_, path);
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
