// Format dispatch by extension; the atomic write itself is in atomic_file.cpp.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <ostream>
#include <string>

#include "rdmesh/atomic_file.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"

namespace rdmesh {
namespace {

namespace fs = std::filesystem;

void write_by_format(const TetMesh& mesh, MeshFormat format, std::ostream& out) {
  switch (format) {
    case MeshFormat::Medit:
      write_medit(mesh, out);
      return;
    case MeshFormat::Gmsh41:
      write_gmsh41(mesh, out);
      return;
    case MeshFormat::Vtu:
      write_vtu(mesh, out);
      return;
  }
  throw InternalError("write_mesh: unhandled MeshFormat");
}

}  // namespace

MeshFormat format_from_path(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".mesh") return MeshFormat::Medit;
  if (ext == ".msh") return MeshFormat::Gmsh41;
  if (ext == ".vtu") return MeshFormat::Vtu;
  throw InputError(path, "unknown output extension '" + ext + "' (expected .mesh, .msh or .vtu)");
}

void write_mesh(const TetMesh& mesh, const std::string& path) {
  const MeshFormat format = format_from_path(path);
  write_file_atomically(path, [&](std::ostream& out) { write_by_format(mesh, format, out); });
}

}  // namespace rdmesh
