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

}  // namespace rdmesh
