// Writing a file so that readers never see a partial one.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>

namespace rdmesh {

/// Calls `writer` on a fresh temporary file "path.tmp-XXXXXX" in path's
/// directory, flushes it to disk and renames it over `path`. On any failure
/// (including an exception from `writer`) the temporary file is removed, a
/// previous file at `path` is left untouched, and OutputError("path: problem")
/// is thrown (exceptions thrown by `writer` other than stream failures propagate).
void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& writer);

/// The same write in two steps, so that a file can be prepared before it is
/// known whether it is wanted: the constructor calls `writer` on a fresh
/// temporary file "path.tmp-XXXXXX" and flushes it to disk (throwing as
/// write_file_atomically does, with nothing left behind); commit() renames it
/// over `path`. Destroyed uncommitted, the temporary file is removed and
/// `path` is left untouched.
class StagedFile {
 public:
  StagedFile(const std::string& path, const std::function<void(std::ostream&)>& writer);
  StagedFile(StagedFile&& other) noexcept;
  StagedFile& operator=(StagedFile&& other) noexcept;
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;
  ~StagedFile();

  /// Replaces `path` with the staged file; OutputError("path: problem") when
  /// the rename fails (the temporary file is then removed). Once only.
  void commit();
  /// The temporary file while it waits (empty once committed or discarded).
  const std::string& temp_path() const { return temp_; }

 private:
  void discard() noexcept;

  std::string path_;
  std::string temp_;
};

}  // namespace rdmesh
