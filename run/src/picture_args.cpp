#include "rdmesh/picture_args.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "rdmesh/errors.h"
#include "rdmesh/run_setup.h"
#include "rdmesh/view_conversion.h"

namespace rdmesh::run {

void add_picture_options(CLI::App& app, PictureArgs& args) {
  app.add_option("--view", args.view, "Picture: view direction iso, x, y or z (default iso)");
  app.add_option("--picture-size", args.size, "Picture: WIDTHxHEIGHT in pixels (default 1600x900)");
  app.add_option("--cut", args.cut,
                 "Picture: the cut plane, AXIS=VALUE such as x=0.2 (default: through the centre, "
                 "normal to the longest axis of the box)");
}

view::PictureOptions picture_options(const PictureArgs& args, const std::string& input) {
  std::string extension = std::filesystem::path(args.path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".png") throw OutputError(args.path + ": a picture is written as .png");
  check_writable(args.path);
  view::PictureOptions options;
  const std::array<int, 2> size = view::parse_picture_size(args.size);
  options.width = size[0];
  options.height = size[1];
  options.view = view::parse_view_direction(args.view);
  if (!args.cut.empty()) options.cut = view::parse_cut(args.cut);
  options.title = std::filesystem::path(input).filename().string();
  return options;
}

void write_picture(const TetMesh& mesh, const PictureArgs& args, const std::string& input) {
  view::render_png(to_view_mesh(mesh), picture_options(args, input), args.path);
}

}  // namespace rdmesh::run
