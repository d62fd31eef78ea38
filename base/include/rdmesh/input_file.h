// One wording for an input file that cannot be read, whatever its kind (domain
// file, triangle mesh, CAD model, mesh to draw), and one reading of its kind
// from its extension.
#pragma once

#include <string>

namespace rdmesh {

/// Throws InputError(path, problem) unless `path` is a regular file this process
/// may read. The problems, the same for every reader: "no such file", "is a
/// directory", "not a regular file (a FIFO, a device...)", "cannot read the file
/// (permission denied)".
void check_input_file(const std::string& path);

/// The extension of `path` in lower case, with its dot (".step"); empty without one.
std::string lower_extension(const std::string& path);

/// True for the extensions load_cad_file reads (.step .stp .brep .iges .igs, any
/// case). Here, not in cad/, so that the command can tell a CAD input without
/// loading OpenCASCADE.
bool is_cad_file(const std::string& path);

}  // namespace rdmesh
