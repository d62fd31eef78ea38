// VTK XML UnstructuredGrid (.vtu) writer: ASCII data arrays, or binary ones
// zlib-compressed and base64-encoded inline (VTK's own binary layout). The
// names of the labels go in the grid's field data.
//
// Cells: all tetrahedra (VTK_TETRA = 10) in input order, then all triangles
// (VTK_TRIANGLE = 5), then the feature edges (VTK_LINE = 3) and the corner
// vertices (VTK_VERTEX = 1). VTK's tetra ordering matches ours (positive volume).
// The "curve" and "corner" cell arrays are written only for meshes with features,
// so that a mesh without them gives the same file as before they existed.
#include <array>
#include <charconv>
#include <ostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "element_nodes.h"
#include "mesh_labels.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/second_order.h"
#include "vtu_binary.h"

namespace rdmesh {
namespace {

constexpr int kVtkTetra = 10;
constexpr int kVtkTriangle = 5;
constexpr int kVtkLine = 3;
constexpr int kVtkVertex = 1;
constexpr int kVtkQuadraticEdge = 21;
constexpr int kVtkQuadraticTriangle = 22;
constexpr int kVtkQuadraticTetra = 24;

/// One DataArray: its tag, its values, its end. ASCII: `per_line` values to a
/// line, the last one followed by a newline. Binary: the values' bytes (the
/// array's own type, little-endian) zlib-compressed in blocks, as VTK's
/// vtkZLibDataCompressor writes them (vtu_binary.h). close() writes the end.
class DataArray {
 public:
  DataArray(std::ostream& out, const char* type, const char* name, std::size_t count,
            std::size_t per_line, bool binary, int components = 1)
      : out_(out), type_(type), count_(count), per_line_(per_line), binary_(binary) {
    out_ << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\"";
    if (components != 1) out_ << " NumberOfComponents=\"" << components << "\"";
    out_ << (binary ? " format=\"binary\">\n" : " format=\"ascii\">\n");
  }
  DataArray(const DataArray&) = delete;
  DataArray& operator=(const DataArray&) = delete;

  void add(long long v) {
    if (binary_) return io_detail::append_binary_value(buffer_, type_, static_cast<double>(v), v);
    io_detail::append_int(buffer_, v);
    next();
  }
  void add_double(double v) {
    if (binary_) return io_detail::append_binary_value(buffer_, type_, v, 0);
    io_detail::append_double(buffer_, v);
    next();
  }
  /// Adds `n` copies of `v`.
  void repeat(long long v, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) add(v);
  }
  void close() {
    if (binary_) {
      out_ << "          " << io_detail::zlib_base64(buffer_) << '\n';
    } else {
      flush();
    }
    out_ << "        </DataArray>\n";
  }

 private:
  void next() {
    ++written_;
    buffer_ += written_ % per_line_ == 0 || written_ == count_ ? '\n' : ' ';
    if (buffer_.size() > 4096) flush();
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

  std::ostream& out_;
  std::string type_;
  std::size_t count_, per_line_, written_ = 0;
  bool binary_;
  std::string buffer_;
};

void write_points(std::ostream& out, const TetMesh& mesh, bool binary) {
  out << "      <Points>\n";
  DataArray a(out, "Float64", "Points", mesh.vertices.size() * 3, 3, binary, 3);
  for (const Point3& p : mesh.vertices) {
    a.add_double(p.x);
    a.add_double(p.y);
    a.add_double(p.z);
  }
  a.close();
  out << "      </Points>\n";
}

std::size_t num_cells(const TetMesh& mesh) {
  return mesh.tets.size() + mesh.triangles.size() + mesh.edges.size() + mesh.corner_vertices.size();
}

/// Appends the node lists of `elements` to `a`.
template <std::size_t N>
void add_nodes(DataArray& a, const std::vector<std::array<int, N>>& elements) {
  for (const auto& e : elements) {
    for (int v : e) a.add(v);
  }
}

void write_cells(std::ostream& out, const TetMesh& mesh, bool binary) {
  const std::size_t nt = mesh.tets.size(), nf = mesh.triangles.size(), ne = mesh.edges.size(),
                    nc = mesh.corner_vertices.size();
  const bool p2 = is_second_order(mesh);
  // Nodes per tetrahedron, triangle, line: 10, 6, 3 for quadratic cells.
  const std::size_t st = p2 ? 10 : 4, sf = p2 ? 6 : 3, se = p2 ? 3 : 2;
  out << "      <Cells>\n";
  {
    DataArray a(out, "Int64", "connectivity", st * nt + sf * nf + se * ne + nc, 12, binary);
    if (p2) {
      add_nodes(a, io_detail::tet10_elements(mesh, io_detail::Tet10Order::kVtk));
      add_nodes(a, io_detail::triangle6_elements(mesh));
      add_nodes(a, io_detail::line3_elements(mesh));
    } else {
      add_nodes(a, mesh.tets);
      add_nodes(a, mesh.triangles);
      add_nodes(a, mesh.edges);
    }
    for (int v : mesh.corner_vertices) a.add(v);
    a.close();
  }
  {
    DataArray a(out, "Int64", "offsets", num_cells(mesh), 12, binary);
    long long offset = 0;
    for (auto [count, size] : {std::pair{nt, st}, {nf, sf}, {ne, se}, {nc, std::size_t{1}}}) {
      for (std::size_t i = 0; i < count; ++i) a.add(offset += static_cast<long long>(size));
    }
    a.close();
  }
  {
    DataArray a(out, "UInt8", "types", num_cells(mesh), 24, binary);
    a.repeat(p2 ? kVtkQuadraticTetra : kVtkTetra, nt);
    a.repeat(p2 ? kVtkQuadraticTriangle : kVtkTriangle, nf);
    a.repeat(p2 ? kVtkQuadraticEdge : kVtkLine, ne);
    a.repeat(kVtkVertex, nc);
    a.close();
  }
  out << "      </Cells>\n";
}

/// One Int32 cell array: zero on every cell except those of block `which`
/// (0 tets, 1 triangles, 2 edges, 3 corners), which get `labels`.
template <class LabelT>
void write_label_array(std::ostream& out, const TetMesh& mesh, const char* name, int which,
                       const std::vector<LabelT>& labels, bool binary) {
  const std::size_t sizes[4] = {mesh.tets.size(), mesh.triangles.size(), mesh.edges.size(),
                                mesh.corner_vertices.size()};
  DataArray a(out, "Int32", name, num_cells(mesh), 24, binary);
  for (int block = 0; block < 4; ++block) {
    if (block == which) {
      for (const LabelT& l : labels) a.add(l.value);
    } else {
      a.repeat(0, sizes[block]);
    }
  }
  a.close();
}

/// The Int32 cell array "partition": every cell's partition (partition.h).
void write_partition_array(std::ostream& out, const TetMesh& mesh, bool binary) {
  DataArray a(out, "Int32", "partition", num_cells(mesh), 24, binary);
  for (const auto* block : {&mesh.tet_partition, &mesh.triangle_partition, &mesh.edge_partition,
                            &mesh.corner_partition}) {
    for (int p : *block) a.add(p);
  }
  a.close();
}

void write_cell_data(std::ostream& out, const TetMesh& mesh, bool binary) {
  out << "      <CellData Scalars=\"subdomain\">\n";
  write_label_array(out, mesh, "subdomain", 0, mesh.tet_subdomain, binary);
  write_label_array(out, mesh, "patch", 1, mesh.triangle_patch, binary);
  if (io_detail::has_features(mesh)) {
    write_label_array(out, mesh, "curve", 2, mesh.edge_curve, binary);
    write_label_array(out, mesh, "corner", 3, mesh.corner_ids, binary);
  }
  if (!mesh.tet_partition.empty()) write_partition_array(out, mesh, binary);
  out << "      </CellData>\n";
}

/// `text` for an XML attribute: & < > " escaped, control characters as spaces.
std::string xml_attribute(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
  }
  return out;
}

/// The names of the subdomains, patches and curves as field data, one Int32
/// array per name holding its id and dimension (meshio reads them as its
/// field_data, as Gmsh's physical names). A name used twice is written once.
void write_field_data(std::ostream& out, const TetMesh& mesh) {
  std::set<std::string> written;
  std::string text;
  const std::pair<std::vector<io_detail::Label>, int> levels[] = {
      {io_detail::subdomain_labels(mesh), 3},
      {io_detail::patch_labels(mesh), 2},
      {io_detail::curve_labels(mesh), 1}};
  for (const auto& [labels, dim] : levels) {
    for (const io_detail::Label& l : labels) {
      const std::string name = io_detail::physical_name(l, dim);
      if (!written.insert(name).second) continue;
      text += "      <DataArray type=\"Int32\" Name=\"" + xml_attribute(name) +
              "\" NumberOfTuples=\"1\" format=\"ascii\">" + std::to_string(l.id) + ' ' +
              std::to_string(dim) + "</DataArray>\n";
    }
  }
  if (!text.empty()) out << "    <FieldData>\n" << text << "    </FieldData>\n";
}

void write_vtu_file(const TetMesh& mesh, std::ostream& out, bool binary) {
  io_detail::check_mesh(mesh);
  // A locale grouping thousands wrote NumberOfPoints="3,600".
  const io_detail::ClassicLocale classic(out);
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\""
      << (binary ? " compressor=\"vtkZLibDataCompressor\"" : "") << ">\n  <UnstructuredGrid>\n";
  write_field_data(out, mesh);
  out << "    <Piece NumberOfPoints=\"" << mesh.vertices.size() << "\" NumberOfCells=\""
      << num_cells(mesh) << "\">\n";
  write_points(out, mesh, binary);
  write_cells(out, mesh, binary);
  write_cell_data(out, mesh, binary);
  out << "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  if (!out) throw OutputError("write_vtu: the output stream failed");
}

}  // namespace

void write_vtu(const TetMesh& mesh, std::ostream& out) { write_vtu_file(mesh, out, false); }

void write_vtu_binary(const TetMesh& mesh, std::ostream& out) { write_vtu_file(mesh, out, true); }

}  // namespace rdmesh
