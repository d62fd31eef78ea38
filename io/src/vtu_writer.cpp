// VTK XML UnstructuredGrid (.vtu) writer, ASCII data arrays.
//
// Cells: all tetrahedra (VTK_TETRA = 10) in input order, then all triangles
// (VTK_TRIANGLE = 5). VTK's tetra ordering matches ours (positive volume).
#include <ostream>
#include <string>

#include "mesh_labels.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"

namespace rdmesh {
namespace {

using io_detail::append_double;
using io_detail::append_int;

constexpr int kVtkTetra = 10;
constexpr int kVtkTriangle = 5;

/// Writes `count` values produced by `value(i)`, several per line.
template <class F>
void write_values(std::ostream& out, std::size_t count, std::size_t per_line, F value) {
  std::string line;
  for (std::size_t i = 0; i < count; ++i) {
    value(line, i);
    line += (i + 1) % per_line == 0 || i + 1 == count ? '\n' : ' ';
    if (line.size() > 4096) {
      out << line;
      line.clear();
    }
  }
  out << line;
}

void open_array(std::ostream& out, const char* type, const char* name, int components = 1) {
  out << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\"";
  if (components != 1) out << " NumberOfComponents=\"" << components << "\"";
  out << " format=\"ascii\">\n";
}

void close_array(std::ostream& out) { out << "        </DataArray>\n"; }

void write_points(std::ostream& out, const TetMesh& mesh) {
  out << "      <Points>\n";
  open_array(out, "Float64", "Points", 3);
  write_values(out, mesh.vertices.size() * 3, 3, [&](std::string& s, std::size_t i) {
    const Point3& p = mesh.vertices[i / 3];
    append_double(s, i % 3 == 0 ? p.x : i % 3 == 1 ? p.y : p.z);
  });
  close_array(out);
  out << "      </Points>\n";
}

void write_cells(std::ostream& out, const TetMesh& mesh) {
  const std::size_t nt = mesh.tets.size(), nf = mesh.triangles.size();
  out << "      <Cells>\n";
  open_array(out, "Int64", "connectivity");
  write_values(out, 4 * nt + 3 * nf, 12, [&](std::string& s, std::size_t i) {
    append_int(s, i < 4 * nt ? mesh.tets[i / 4][i % 4]
                             : mesh.triangles[(i - 4 * nt) / 3][(i - 4 * nt) % 3]);
  });
  close_array(out);
  open_array(out, "Int64", "offsets");
  write_values(out, nt + nf, 12, [&](std::string& s, std::size_t i) {
    append_int(s, static_cast<long long>(i < nt ? 4 * (i + 1) : 4 * nt + 3 * (i + 1 - nt)));
  });
  close_array(out);
  open_array(out, "UInt8", "types");
  write_values(out, nt + nf, 24, [&](std::string& s, std::size_t i) {
    append_int(s, i < nt ? kVtkTetra : kVtkTriangle);
  });
  close_array(out);
  out << "      </Cells>\n";
}

void write_cell_data(std::ostream& out, const TetMesh& mesh) {
  const std::size_t nt = mesh.tets.size(), nf = mesh.triangles.size();
  out << "      <CellData Scalars=\"subdomain\">\n";
  open_array(out, "Int32", "subdomain");
  write_values(out, nt + nf, 24, [&](std::string& s, std::size_t i) {
    append_int(s, i < nt ? mesh.tet_subdomain[i].value : 0);
  });
  close_array(out);
  open_array(out, "Int32", "patch");
  write_values(out, nt + nf, 24, [&](std::string& s, std::size_t i) {
    append_int(s, i < nt ? 0 : mesh.triangle_patch[i - nt].value);
  });
  close_array(out);
  out << "      </CellData>\n";
}

}  // namespace

void write_vtu(const TetMesh& mesh, std::ostream& out) {
  io_detail::check_mesh(mesh);
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n"
         "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << mesh.vertices.size() << "\" NumberOfCells=\""
      << mesh.tets.size() + mesh.triangles.size() << "\">\n";
  write_points(out, mesh);
  write_cells(out, mesh);
  write_cell_data(out, mesh);
  out << "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  if (!out) throw OutputError("write_vtu: the output stream failed");
}

}  // namespace rdmesh
