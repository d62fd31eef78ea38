// The picture options shared by meshing runs (--picture FILE.png) and the
// view command (rdmesh view MESH -o FILE.png).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "rdmesh/picture.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh::run {

struct PictureArgs {
  std::string path;  ///< the PNG to write; empty: none
  std::string view = "iso";
  std::string size = "1600x900";
  std::string cut;  ///< "x=0.2"; empty: the default plane
};

/// --view, --picture-size and --cut (the path option is the caller's).
void add_picture_options(CLI::App& app, PictureArgs& args);

/// The parsed options, with `input`'s file name as the legend's title.
/// Throws InputError for a bad value, OutputError when args.path does not end
/// in .png or its directory is not writable.
view::PictureOptions picture_options(const PictureArgs& args, const std::string& input);

/// Writes the picture of `mesh` to args.path (atomically).
void write_picture(const TetMesh& mesh, const PictureArgs& args, const std::string& input);

}  // namespace rdmesh::run
