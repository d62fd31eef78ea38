// One wording for an input file that cannot be read, whatever its kind (domain
// file, triangle mesh, CAD model, mesh to draw).
#pragma once

#include <string>

namespace rdmesh {

/// Throws InputError(path, problem) unless `path` is a regular file this process
/// may read. The problems, the same for every reader: "no such file", "is a
/// directory", "not a regular file (a FIFO, a device...)", "cannot read the file
/// (permission denied)".
void check_input_file(const std::string& path);

}  // namespace rdmesh
