// Runs the rdmesh executable in a scratch directory and captures its output.
#pragma once

#include <filesystem>
#include <string>

namespace rdmesh::test {

struct CliRun {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr interleaved
};

/// A fresh directory under the system temp dir, removed on destruction.
class ScratchDir {
 public:
  ScratchDir();
  ~ScratchDir();
  const std::filesystem::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  /// Writes `text` to `name` in the directory and returns its path.
  std::string write(const std::string& name, const std::string& text) const;
  /// Number of entries in the directory.
  std::size_t entries() const;

 private:
  std::filesystem::path path_;
};

/// Runs `rdmesh ARGS` (ARGS already shell-quoted) with `dir` as working directory.
CliRun run_cli(const std::string& args, const std::filesystem::path& dir);
/// The same with another executable (`program`, a path).
CliRun run_command(const std::string& program, const std::string& args,
                   const std::filesystem::path& dir);

/// CPU seconds (user + system) used so far by this process (RUSAGE_SELF), or
/// by its children that ended and were waited for, their own children
/// included (RUSAGE_CHILDREN): what a test asserts about a limit in CPU
/// seconds, which a loaded machine does not change as it changes wall time.
double own_cpu_seconds();
double children_cpu_seconds();

/// The bytes of the file at `path` (empty when it cannot be read).
std::string read_file(const std::string& path);

/// Path of a file in the source tree (e.g. "samples/sphere.json").
std::string source_path(const std::string& relative);

}  // namespace rdmesh::test
