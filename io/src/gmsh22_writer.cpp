// Gmsh MSH 2.2 ASCII writer, for solvers that read no 4.1: the physical names,
// all nodes, and every element with its physical group and elementary entity
// (the same id: subdomain, patch, curve or corner).
#include <array>
#include <ostream>
#include <string>
#include <vector>

#include "element_nodes.h"
#include "mesh_labels.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/second_order.h"

namespace rdmesh {
namespace {

/// Element lines "tag type 2 id id v1 v2 ..." (1-based) of one kind.
template <class Elements, class Labels>
void write_elements(std::string& text, long long& tag, int gmsh_type, const Elements& elements,
                    const Labels& labels) {
  for (std::size_t e = 0; e < elements.size(); ++e) {
    io_detail::append_int(text, tag++);
    text += ' ';
    io_detail::append_int(text, gmsh_type);
    text += " 2 ";
    io_detail::append_int(text, labels[e].value);
    text += ' ';
    io_detail::append_int(text, labels[e].value);
    for (int v : elements[e]) {
      text += ' ';
      io_detail::append_int(text, v + 1);
    }
    text += '\n';
  }
}

}  // namespace

void write_gmsh22(const TetMesh& mesh, std::ostream& out) {
  io_detail::check_mesh(mesh);
  // A locale grouping thousands wrote the node count as "3,600".
  const io_detail::ClassicLocale classic(out);
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  const std::vector<io_detail::Label> levels[4] = {
      io_detail::corner_labels(mesh), io_detail::curve_labels(mesh), io_detail::patch_labels(mesh),
      io_detail::subdomain_labels(mesh)};
  out << "$PhysicalNames\n"
      << levels[0].size() + levels[1].size() + levels[2].size() + levels[3].size() << '\n';
  for (int dim : {3, 2, 1, 0}) {
    for (const io_detail::Label& l : levels[dim]) {
      out << dim << ' ' << l.id << ' ' << io_detail::quoted_physical_name(l, dim) << '\n';
    }
  }
  out << "$EndPhysicalNames\n$Nodes\n" << mesh.vertices.size() << '\n';
  std::string text;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Point3& p = mesh.vertices[i];
    io_detail::append_int(text, static_cast<long long>(i + 1));
    for (double c : {p.x, p.y, p.z}) {
      text += ' ';
      io_detail::append_double(text, c);
    }
    text += '\n';
  }
  out << text << "$EndNodes\n$Elements\n"
      << mesh.tets.size() + mesh.triangles.size() + mesh.edges.size() + mesh.corner_vertices.size()
      << '\n';
  text.clear();
  long long tag = 1;
  if (is_second_order(mesh)) {  // 10-node tets, 6-node triangles, 3-node lines
    write_elements(text, tag, 11, io_detail::tet10_elements(mesh, io_detail::Tet10Order::kGmsh),
                   mesh.tet_subdomain);
    write_elements(text, tag, 9, io_detail::triangle6_elements(mesh), mesh.triangle_patch);
    write_elements(text, tag, 8, io_detail::line3_elements(mesh), mesh.edge_curve);
  } else {
    write_elements(text, tag, 4, mesh.tets, mesh.tet_subdomain);
    write_elements(text, tag, 2, mesh.triangles, mesh.triangle_patch);
    write_elements(text, tag, 1, mesh.edges, mesh.edge_curve);
  }
  std::vector<std::array<int, 1>> corners;
  for (int v : mesh.corner_vertices) corners.push_back({v});
  write_elements(text, tag, 15, corners, mesh.corner_ids);
  out << text << "$EndElements\n";
  if (!out) throw OutputError("write_gmsh22: the output stream failed");
}

}  // namespace rdmesh
