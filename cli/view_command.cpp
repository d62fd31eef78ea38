#include "view_command.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <string>

#include "rdmesh/arguments.h"
#include "rdmesh/errors.h"
#include "rdmesh/picture.h"
#include "rdmesh/picture_args.h"
#include "rdmesh/view_mesh.h"

namespace rdmesh::cli {
namespace {

int view(const std::string& input, run::PictureArgs& args, bool quiet) {
  if (args.path.empty()) args.path = std::filesystem::path(input).stem().string() + ".png";
  const view::PictureOptions options =
      run::picture_options(args, input);  // bad options: before reading
  const view::ViewMesh mesh = view::read_view_mesh(input);
  view::render_png(mesh, options, args.path);
  if (!quiet) {
    std::printf("%s: %zu tetrahedra, %zu triangles -> %s (%dx%d)\n", input.c_str(),
                mesh.tets.size(), mesh.triangles.size(), args.path.c_str(), options.width,
                options.height);
  }
  return 0;
}

}  // namespace

int run_view_command(int argc, char** argv) {
  CLI::App app{"rdmesh view: a picture of a tetrahedral mesh (.msh, .mesh or .vtu)", "rdmesh view"};
  std::string input;
  run::PictureArgs args;
  bool quiet = false;
  app.add_option("mesh", input, "Mesh file: .msh (Gmsh 4.1 or 2.2 ASCII), .mesh (Medit) or .vtu")
      ->required();
  app.add_option("-o,--output", args.path, "The picture, .png (default: MESH-stem.png)");
  run::add_picture_options(app, args);
  app.add_flag("-q,--quiet", quiet, "No summary line");
  if (const auto flag = run::single_dash_option(argc, argv, "oqh")) {
    std::fprintf(stderr, "rdmesh: error: %s\n",
                 run::unknown_single_dash_message(*flag, "rdmesh view").c_str());
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "rdmesh: error: %s\n",
                 run::parse_error_message(e, app, "rdmesh view").c_str());
    return 2;
  }
  try {
    return view(input, args, quiet);
  } catch (const InputError& e) {
    std::fprintf(stderr, "rdmesh: error: %s\n", e.what());
    return 2;
  } catch (const OutputError& e) {
    std::fprintf(stderr, "rdmesh: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rdmesh: error: internal error: %s\n", e.what());
    return 3;
  }
}

}  // namespace rdmesh::cli
