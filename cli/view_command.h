// rdmesh view MESH [-o FILE.png] [--view ...] [--picture-size ...] [--cut ...]:
// a picture of an existing .msh, .mesh or .vtu file, from rdmesh or another tool.
#pragma once

namespace rdmesh::cli {

/// The view command; argv[0] is "view". Returns the exit code: 0 with the
/// picture written, 2 (one line on stderr) for a bad mesh file, bad options
/// or an unwritable output, 3 for an internal error.
int run_view_command(int argc, char** argv);

}  // namespace rdmesh::cli
