// VTK XML UnstructuredGrid (.vtu) writer, ASCII data arrays.
//
// Cells: all tetrahedra (VTK_TETRA = 10) in input order, then all triangles
// (VTK_TRIANGLE = 5), then the feature edges (VTK_LINE = 3) and the corner
// vertices (VTK_VERTEX = 1). VTK's tetra ordering matches ours (positive volume).
// The "curve" and "corner" cell arrays are written only for meshes with features,
// so that a mesh without them gives the same file as before they existed.
#include <array>
#include <charconv>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "element_nodes.h"
#include "mesh_labels.h"
#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/second_order.h"

namespace rdmesh {
namespace {

using io_detail::append_double;
using io_detail::append_int;

constexpr int kVtkTetra = 10;
constexpr int kVtkTriangle = 5;
constexpr int kVtkLine = 3;
constexpr int kVtkVertex = 1;
constexpr int kVtkQuadraticEdge = 21;
constexpr int kVtkQuadraticTriangle = 22;
constexpr int kVtkQuadraticTetra = 24;

/// Streams integers, `per_line` to a line, the last one followed by a newline.
/// Buffers in a fixed array (flushed by the destructor at the latest).
class IntWriter {
 public:
  IntWriter(std::ostream& out, std::size_t count, std::size_t per_line)
      : out_(out), count_(count), per_line_(per_line) {}
  IntWriter(const IntWriter&) = delete;
  IntWriter& operator=(const IntWriter&) = delete;
  ~IntWriter() { flush(); }

  void add(long long v) {
    if (size_ + 32 > buffer_.size()) flush();
    const auto res = std::to_chars(buffer_.data() + size_, buffer_.data() + buffer_.size(), v);
    size_ = static_cast<std::size_t>(res.ptr - buffer_.data());
    ++written_;
    buffer_[size_++] = written_ % per_line_ == 0 || written_ == count_ ? '\n' : ' ';
  }
  /// Adds `n` copies of `v`.
  void repeat(long long v, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) add(v);
  }

 private:
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(size_));
    size_ = 0;
  }

  std::ostream& out_;
  std::size_t count_, per_line_, written_ = 0, size_ = 0;
  std::array<char, 4096> buffer_{};
};

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

std::size_t num_cells(const TetMesh& mesh) {
  return mesh.tets.size() + mesh.triangles.size() + mesh.edges.size() + mesh.corner_vertices.size();
}

/// Appends the node lists of `elements` to `w`.
template <std::size_t N>
void add_nodes(IntWriter& w, const std::vector<std::array<int, N>>& elements) {
  for (const auto& e : elements) {
    for (int v : e) w.add(v);
  }
}

void write_cells(std::ostream& out, const TetMesh& mesh) {
  const std::size_t nt = mesh.tets.size(), nf = mesh.triangles.size(), ne = mesh.edges.size(),
                    nc = mesh.corner_vertices.size();
  const bool p2 = is_second_order(mesh);
  // Nodes per tetrahedron, triangle, line: 10, 6, 3 for quadratic cells.
  const std::size_t st = p2 ? 10 : 4, sf = p2 ? 6 : 3, se = p2 ? 3 : 2;
  out << "      <Cells>\n";
  open_array(out, "Int64", "connectivity");
  {
    IntWriter w(out, st * nt + sf * nf + se * ne + nc, 12);
    if (p2) {
      add_nodes(w, io_detail::tet10_elements(mesh, io_detail::Tet10Order::kVtk));
      add_nodes(w, io_detail::triangle6_elements(mesh));
      add_nodes(w, io_detail::line3_elements(mesh));
    } else {
      add_nodes(w, mesh.tets);
      add_nodes(w, mesh.triangles);
      add_nodes(w, mesh.edges);
    }
    for (int v : mesh.corner_vertices) w.add(v);
  }
  close_array(out);
  open_array(out, "Int64", "offsets");
  {
    IntWriter w(out, num_cells(mesh), 12);
    long long offset = 0;
    for (auto [count, size] : {std::pair{nt, st}, {nf, sf}, {ne, se}, {nc, std::size_t{1}}}) {
      for (std::size_t i = 0; i < count; ++i) w.add(offset += static_cast<long long>(size));
    }
  }
  close_array(out);
  open_array(out, "UInt8", "types");
  {
    IntWriter w(out, num_cells(mesh), 24);
    w.repeat(p2 ? kVtkQuadraticTetra : kVtkTetra, nt);
    w.repeat(p2 ? kVtkQuadraticTriangle : kVtkTriangle, nf);
    w.repeat(p2 ? kVtkQuadraticEdge : kVtkLine, ne);
    w.repeat(kVtkVertex, nc);
  }
  close_array(out);
  out << "      </Cells>\n";
}

/// One Int32 cell array: zero on every cell except those of block `which`
/// (0 tets, 1 triangles, 2 edges, 3 corners), which get `labels`.
template <class LabelT>
void write_label_array(std::ostream& out, const TetMesh& mesh, const char* name, int which,
                       const std::vector<LabelT>& labels) {
  const std::size_t sizes[4] = {mesh.tets.size(), mesh.triangles.size(), mesh.edges.size(),
                                mesh.corner_vertices.size()};
  open_array(out, "Int32", name);
  {
    IntWriter w(out, num_cells(mesh), 24);
    for (int block = 0; block < 4; ++block) {
      if (block == which) {
        for (const LabelT& l : labels) w.add(l.value);
      } else {
        w.repeat(0, sizes[block]);
      }
    }
  }
  close_array(out);
}

/// The Int32 cell array "partition": every cell's partition (partition.h).
void write_partition_array(std::ostream& out, const TetMesh& mesh) {
  open_array(out, "Int32", "partition");
  {
    IntWriter w(out, num_cells(mesh), 24);
    for (const auto* block : {&mesh.tet_partition, &mesh.triangle_partition, &mesh.edge_partition,
                              &mesh.corner_partition}) {
      for (int p : *block) w.add(p);
    }
  }
  close_array(out);
}

void write_cell_data(std::ostream& out, const TetMesh& mesh) {
  out << "      <CellData Scalars=\"subdomain\">\n";
  write_label_array(out, mesh, "subdomain", 0, mesh.tet_subdomain);
  write_label_array(out, mesh, "patch", 1, mesh.triangle_patch);
  if (io_detail::has_features(mesh)) {
    write_label_array(out, mesh, "curve", 2, mesh.edge_curve);
    write_label_array(out, mesh, "corner", 3, mesh.corner_ids);
  }
  if (!mesh.tet_partition.empty()) write_partition_array(out, mesh);
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
      << num_cells(mesh) << "\">\n";
  write_points(out, mesh);
  write_cells(out, mesh);
  write_cell_data(out, mesh);
  out << "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  if (!out) throw OutputError("write_vtu: the output stream failed");
}

}  // namespace rdmesh
