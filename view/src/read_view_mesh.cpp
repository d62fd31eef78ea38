// Reading a mesh file by extension, and the checks every reader's output passes.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "element_kinds.h"
#include "rdmesh/errors.h"
#include "rdmesh/input_file.h"
#include "rdmesh/view_mesh.h"
#include "text_scanner.h"

namespace rdmesh::view {
namespace {

template <std::size_t N>
void check_elements(const std::vector<std::array<int, N>>& elements, std::size_t labels,
                    std::size_t points, const char* what, const std::string& file) {
  if (labels != elements.size()) {
    throw InputError(file, std::string("the ") + what + " and their labels differ in number");
  }
  for (std::size_t e = 0; e < elements.size(); ++e) {
    for (int v : elements[e]) {
      if (v < 0 || static_cast<std::size_t>(v) >= points) {
        throw InputError(file, std::string(what) + " " + std::to_string(e + 1) +
                                   " refers to a point that does not exist (" +
                                   std::to_string(points) + " points)");
      }
    }
  }
}

std::string read_file(const std::string& path) {
  check_input_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  if (!in.good() && !in.eof()) throw InputError(path, "cannot read the file");
  return std::move(text).str();
}

}  // namespace

namespace detail {

void add_element(ViewMesh& mesh, Kind kind, const int* nodes, int label) {
  switch (kind) {
    case Kind::kPoint:
      mesh.corners.push_back(nodes[0]);
      break;
    case Kind::kLine:
      mesh.edges.push_back({nodes[0], nodes[1]});
      mesh.edge_labels.push_back(label);
      break;
    case Kind::kTriangle:
      mesh.triangles.push_back({nodes[0], nodes[1], nodes[2]});
      mesh.triangle_labels.push_back(label);
      break;
    case Kind::kTet:
      mesh.tets.push_back({nodes[0], nodes[1], nodes[2], nodes[3]});
      mesh.tet_labels.push_back(label);
      break;
    case Kind::kOther:
      ++mesh.skipped_elements;
      break;
  }
}

}  // namespace detail

void check_view_mesh(const ViewMesh& mesh, const std::string& file) {
  const std::size_t n = mesh.points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point3& p = mesh.points[i];
    if (!is_finite(p)) {
      throw InputError(file,
                       "point " + std::to_string(i + 1) + " has a coordinate that is not finite");
    }
  }
  check_elements(mesh.tets, mesh.tet_labels.size(), n, "tetrahedron", file);
  check_elements(mesh.triangles, mesh.triangle_labels.size(), n, "triangle", file);
  check_elements(mesh.edges, mesh.edge_labels.size(), n, "edge", file);
  for (std::size_t c = 0; c < mesh.corners.size(); ++c) {
    if (mesh.corners[c] < 0 || static_cast<std::size_t>(mesh.corners[c]) >= n) {
      throw InputError(
          file, "corner " + std::to_string(c + 1) + " refers to a point that does not exist");
    }
  }
}

ViewMesh read_view_mesh(const std::string& path) {
  const std::string extension = detail::lower(std::filesystem::path(path).extension().string());
  if (extension != ".msh" && extension != ".mesh" && extension != ".vtu") {
    throw InputError(path,
                     "unknown mesh extension '" + extension + "' (expected .msh, .mesh or .vtu)");
  }
  const std::string text = read_file(path);
  ViewMesh mesh = extension == ".msh"    ? parse_gmsh(text, path)
                  : extension == ".mesh" ? parse_medit(text, path)
                                         : parse_vtu(text, path);
  check_view_mesh(mesh, path);
  if (mesh.tets.empty() && mesh.triangles.empty()) {
    throw InputError(path, "the mesh has neither tetrahedra nor triangles to draw");
  }
  return mesh;
}

}  // namespace rdmesh::view
