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

std::size_t element_count(const TetMesh& mesh) {
  return mesh.tets.size() + mesh.triangles.size() + mesh.edges.size() + mesh.corner_vertices.size();
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

bool writes_binary(const TetMesh& mesh, MeshFormat format, const WriteOptions& options) {
  if (options.msh22 && format != MeshFormat::Gmsh41 && format != MeshFormat::Gmsh22) {
    throw InputError("MSH 2.2 is a .msh format; the output is not .msh");
  }
  const bool text_only =
      format == MeshFormat::Medit || format == MeshFormat::Gmsh22 || options.msh22;
  if (options.encoding == Encoding::binary && text_only) {
    throw InputError(std::string(format == MeshFormat::Medit ? "Medit .mesh" : "MSH 2.2") +
                     " is written as text only (binary: .msh 4.1 or .vtu)");
  }
  if (text_only || options.encoding == Encoding::ascii) return false;
  return options.encoding == Encoding::binary || element_count(mesh) > kBinaryAboveElements;
}

void write_mesh(const TetMesh& mesh, const std::string& path, const WriteOptions& options) {
  stage_mesh(mesh, path, options).commit();
}

StagedFile stage_mesh(const TetMesh& mesh, const std::string& path, const WriteOptions& options) {
  const MeshFormat format = format_from_path(path);
  bool binary = false;
  try {
    binary = writes_binary(mesh, format, options);
  } catch (const InputError& e) {
    throw InputError(path, e.what());
  }
  return StagedFile(path, [&](std::ostream& out) {
    switch (format) {
      case MeshFormat::Medit:
        return write_medit(mesh, out);
      case MeshFormat::Gmsh41:
      case MeshFormat::Gmsh22:
        if (options.msh22 || format == MeshFormat::Gmsh22) return write_gmsh22(mesh, out);
        return binary ? write_gmsh41_binary(mesh, out) : write_gmsh41(mesh, out);
      case MeshFormat::Vtu:
        return binary ? write_vtu_binary(mesh, out) : write_vtu(mesh, out);
    }
    throw InternalError("write_mesh: unhandled MeshFormat");
  });
}

}  // namespace rdmesh
