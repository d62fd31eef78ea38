// Medit .mesh writer (MeshVersionFormatted 2, Dimension 3).
//
// Feature data, written only when present: Edges (ref = curve id), Corners
// (vertex indices), and the corner id as the reference of each corner vertex
// (other vertices keep ref 0), since the Corners keyword carries no id.
#include <ostream>
#include <vector>

#include "element_nodes.h"
#include "mesh_labels.h"
#include "number_tokens.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/second_order.h"

namespace rdmesh {
namespace {

/// Writes one element section: keyword, count, then "i1 ... iN ref" per element (1-based).
template <std::size_t N, class LabelT>
void write_section(std::ostream& out, const char* keyword,
                   const std::vector<std::array<int, N>>& elements,
                   const std::vector<LabelT>& labels) {
  out << keyword << '\n';
  io_detail::NumberTokens t(out, false);  // numbers whatever the stream's locale
  t.z(static_cast<long long>(elements.size()));
  t.end_line();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    for (int v : elements[e]) t.i(v + 1);
    t.i(labels[e].value);
    t.end_line();
  }
}

/// TetrahedraP2, TrianglesP2 and EdgesP2: the vertices, then the mid nodes
/// in P.L. George's order (tetrahedra: edges 01, 12, 20, 03, 13, 23).
void write_p2_sections(std::ostream& out, const TetMesh& mesh) {
  write_section(out, "TetrahedraP2", io_detail::tet10_elements(mesh, io_detail::Tet10Order::kVtk),
                mesh.tet_subdomain);
  out << '\n';
  write_section(out, "TrianglesP2", io_detail::triangle6_elements(mesh), mesh.triangle_patch);
  if (!mesh.edges.empty()) {
    out << '\n';
    write_section(out, "EdgesP2", io_detail::line3_elements(mesh), mesh.edge_curve);
  }
}

}  // namespace

void write_medit(const TetMesh& mesh, std::ostream& out) {
  io_detail::check_mesh(mesh);
  out << "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n";
  std::vector<int> vertex_ref(mesh.vertices.size(), 0);
  for (std::size_t c = 0; c < mesh.corner_vertices.size(); ++c) {
    vertex_ref[mesh.corner_vertices[c]] = mesh.corner_ids[c].value;
  }
  {
    io_detail::NumberTokens t(out, false);
    t.z(static_cast<long long>(mesh.vertices.size()));
    t.end_line();
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      const Point3& p = mesh.vertices[i];
      t.d(p.x);
      t.d(p.y);
      t.d(p.z);
      t.i(vertex_ref[i]);
      t.end_line();
    }
  }
  out << '\n';
  if (is_second_order(mesh)) {
    write_p2_sections(out, mesh);
  } else {
    write_section(out, "Tetrahedra", mesh.tets, mesh.tet_subdomain);
    out << '\n';
    write_section(out, "Triangles", mesh.triangles, mesh.triangle_patch);
    if (!mesh.edges.empty()) {
      out << '\n';
      write_section(out, "Edges", mesh.edges, mesh.edge_curve);
    }
  }
  if (!mesh.corner_vertices.empty()) {
    out << "\nCorners\n";
    io_detail::NumberTokens t(out, false);
    t.z(static_cast<long long>(mesh.corner_vertices.size()));
    t.end_line();
    for (int v : mesh.corner_vertices) {
      t.i(v + 1);
      t.end_line();
    }
  }
  out << "\nEnd\n";
  if (!out) throw OutputError("write_medit: the output stream failed");
}

}  // namespace rdmesh
