// Medit .mesh writer (MeshVersionFormatted 2, Dimension 3).
//
// Feature data, written only when present: Edges (ref = curve id), Corners
// (vertex indices), and the corner id as the reference of each corner vertex
// (other vertices keep ref 0), since the Corners keyword carries no id.
#include <ostream>
#include <string>
#include <vector>

#include "mesh_labels.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"

namespace rdmesh {
namespace {

using io_detail::append_double;
using io_detail::append_int;

/// Writes one element section: keyword, count, then "i1 ... iN ref" per element (1-based).
template <std::size_t N, class LabelT>
void write_section(std::ostream& out, const char* keyword,
                   const std::vector<std::array<int, N>>& elements,
                   const std::vector<LabelT>& labels) {
  std::string line = std::string(keyword) + "\n";
  append_int(line, static_cast<long long>(elements.size()));
  line += '\n';
  out << line;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    line.clear();
    for (int v : elements[e]) {
      append_int(line, v + 1);
      line += ' ';
    }
    append_int(line, labels[e].value);
    line += '\n';
    out << line;
  }
}

}  // namespace

void write_medit(const TetMesh& mesh, std::ostream& out) {
  io_detail::check_mesh(mesh);
  out << "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n" << mesh.vertices.size() << '\n';
  std::vector<int> vertex_ref(mesh.vertices.size(), 0);
  for (std::size_t c = 0; c < mesh.corner_vertices.size(); ++c) {
    vertex_ref[mesh.corner_vertices[c]] = mesh.corner_ids[c].value;
  }
  std::string line;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Point3& p = mesh.vertices[i];
    line.clear();
    append_double(line, p.x);
    line += ' ';
    append_double(line, p.y);
    line += ' ';
    append_double(line, p.z);
    line += ' ';
    append_int(line, vertex_ref[i]);
    line += '\n';
    out << line;
  }
  out << '\n';
  write_section(out, "Tetrahedra", mesh.tets, mesh.tet_subdomain);
  out << '\n';
  write_section(out, "Triangles", mesh.triangles, mesh.triangle_patch);
  if (!mesh.edges.empty()) {
    out << '\n';
    write_section(out, "Edges", mesh.edges, mesh.edge_curve);
  }
  if (!mesh.corner_vertices.empty()) {
    line = "\nCorners\n";
    append_int(line, static_cast<long long>(mesh.corner_vertices.size()));
    line += '\n';
    for (int v : mesh.corner_vertices) {
      append_int(line, v + 1);
      line += '\n';
    }
    out << line;
  }
  out << "\nEnd\n";
  if (!out) throw OutputError("write_medit: the output stream failed");
}

}  // namespace rdmesh
