// VTK XML UnstructuredGrid (.vtu) reader: what rdmesh writes (ascii) and what
// ParaView, meshio or VTK write (inline binary, appended raw or base64, zlib).
//
// The XML is scanned, not fully parsed: the reader needs the VTKFile settings,
// each Piece's point count, and its DataArrays by section (Points, Cells,
// CellData); the appended section is binary and ends the scan. Pieces are
// concatenated. Labels come from the cell arrays rdmesh writes ("subdomain" on
// tetrahedra, "patch" on triangles, "curve" on lines), else from a common tag
// array of other tools ("gmsh:physical", "medit:ref", "CellEntityIds", ...),
// else from the first integer cell array; cells of other shapes are skipped.
#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "element_kinds.h"
#include "rdmesh/errors.h"
#include "rdmesh/view_mesh.h"
#include "vtu_data.h"

namespace rdmesh::view {
namespace {

using detail::Kind;

struct XmlTag {
  std::string_view name;
  std::string_view attributes;
  bool closing = false;       ///< </name>
  bool self_closing = false;  ///< <name ... />
  std::size_t end = 0;        ///< position after '>'
};

/// The value of attribute `key` in `attributes` (empty when absent).
std::string attribute(std::string_view attributes, std::string_view key) {
  std::size_t pos = 0;
  while ((pos = attributes.find(key, pos)) != std::string_view::npos) {
    const bool starts = pos == 0 || attributes[pos - 1] == ' ' || attributes[pos - 1] == '\n' ||
                        attributes[pos - 1] == '\t' || attributes[pos - 1] == '\r';
    std::size_t p = pos + key.size();
    while (p < attributes.size() && attributes[p] == ' ') ++p;
    if (starts && p < attributes.size() && attributes[p] == '=') {
      ++p;
      while (p < attributes.size() && attributes[p] == ' ') ++p;
      if (p < attributes.size() && (attributes[p] == '"' || attributes[p] == '\'')) {
        const std::size_t close = attributes.find(attributes[p], p + 1);
        if (close != std::string_view::npos)
          return std::string(attributes.substr(p + 1, close - p - 1));
      }
      return {};
    }
    pos += key.size();
  }
  return {};
}

struct Array {
  detail::ArraySource source;
  std::string section;  ///< "Points", "Cells", "CellData", ...
  int components = 1;
  bool appended = false;
  std::size_t offset = 0;
};

struct Piece {
  std::size_t num_points = 0, num_cells = 0;
  std::vector<Array> arrays;
};

class VtuReader {
 public:
  VtuReader(const std::string& text, const std::string& file) : text_(text), file_(file) {}

  ViewMesh read() {
    scan();
    if (pieces_.empty()) fail("no Piece in the UnstructuredGrid");
    resolve_appended();
    for (const Piece& piece : pieces_) read_piece(piece);
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw InputError(file_, problem); }

  /// The next tag at or after `pos`, skipping declarations, comments and text.
  bool next_tag(std::size_t& pos, XmlTag& tag) const {
    while (true) {
      const std::size_t open = text_.find('<', pos);
      if (open == std::string_view::npos) return false;
      if (text_.compare(open, 4, "<!--") == 0) {
        const std::size_t close = text_.find("-->", open);
        if (close == std::string_view::npos) fail("unterminated XML comment");
        pos = close + 3;
        continue;
      }
      const std::size_t close = text_.find('>', open);
      if (close == std::string_view::npos) fail("unterminated XML tag");
      pos = close + 1;
      if (text_[open + 1] == '?' || text_[open + 1] == '!') continue;
      std::string_view inner = text_.substr(open + 1, close - open - 1);
      tag = XmlTag{};
      tag.end = pos;
      if (!inner.empty() && inner.front() == '/') {
        tag.closing = true;
        inner.remove_prefix(1);
      }
      if (!inner.empty() && inner.back() == '/') {
        tag.self_closing = true;
        inner.remove_suffix(1);
      }
      const std::size_t space = inner.find_first_of(" \t\r\n");
      tag.name = inner.substr(0, space);
      tag.attributes = space == std::string_view::npos ? std::string_view() : inner.substr(space);
      return true;
    }
  }

  void read_file_settings(const XmlTag& tag) {
    const std::string type = attribute(tag.attributes, "type");
    if (type != "UnstructuredGrid") fail("not a VTK UnstructuredGrid (type \"" + type + "\")");
    const std::string header = attribute(tag.attributes, "header_type");
    if (!header.empty() && header != "UInt32" && header != "UInt64")
      fail("unknown header_type " + header);
    encoding_.header64 = header == "UInt64";
    encoding_.big_endian = attribute(tag.attributes, "byte_order") == "BigEndian";
    const std::string compressor = attribute(tag.attributes, "compressor");
    if (!compressor.empty() && compressor != "vtkZLibDataCompressor") {
      fail("compressor " + compressor + " is not supported (zlib is)");
    }
    encoding_.zlib = !compressor.empty();
    have_file_ = true;
  }

  std::size_t count_attribute(const XmlTag& tag, const char* key) const {
    const std::string value = attribute(tag.attributes, key);
    std::size_t n = 0;
    try {
      std::size_t used = 0;
      n = std::stoull(value, &used);
      if (used != value.size()) throw std::invalid_argument(key);
    } catch (const std::exception&) {
      fail(std::string("Piece has no valid ") + key);
    }
    return n;
  }

  void add_array(const XmlTag& tag, std::size_t& pos, const std::string& section) {
    if (pieces_.empty()) fail("DataArray outside a Piece");
    Array a;
    a.section = section;
    a.source.name = attribute(tag.attributes, "Name");
    a.source.type = attribute(tag.attributes, "type");
    a.source.format = attribute(tag.attributes, "format");
    const std::string components = attribute(tag.attributes, "NumberOfComponents");
    a.components = components.empty() ? 1 : std::max(1, std::atoi(components.c_str()));
    if (a.source.format == "appended") {
      a.appended = true;
      const std::string offset = attribute(tag.attributes, "offset");
      if (offset.empty() || offset.find_first_not_of("0123456789") != std::string::npos) {
        fail("appended DataArray '" + a.source.name + "' has no valid offset");
      }
      a.offset = std::stoull(offset);
    }
    if (!tag.self_closing) {
      const std::size_t close = text_.find("</DataArray", pos);
      if (close == std::string_view::npos) fail("unterminated DataArray '" + a.source.name + "'");
      a.source.text = text_.substr(pos, close - pos);
      pos = close;
    }
    pieces_.back().arrays.push_back(std::move(a));
  }

  void scan() {
    std::size_t pos = 0;
    XmlTag tag;
    std::string section;
    while (next_tag(pos, tag)) {
      if (tag.name == "VTKFile" && !tag.closing) {
        read_file_settings(tag);
      } else if (!have_file_) {
        fail("not a VTK XML file (no VTKFile element)");
      } else if (tag.name == "Piece" && !tag.closing) {
        pieces_.push_back(
            {count_attribute(tag, "NumberOfPoints"), count_attribute(tag, "NumberOfCells"), {}});
      } else if (tag.name == "DataArray" && !tag.closing && section == "FieldData") {
        // Field data (names of the labels, say) carries nothing to draw: skipped.
        if (!tag.self_closing) {
          const std::size_t close = text_.find("</DataArray", pos);
          if (close == std::string_view::npos) fail("unterminated DataArray in FieldData");
          pos = close;
        }
      } else if (tag.name == "DataArray" && !tag.closing) {
        add_array(tag, pos, section);
      } else if (tag.name == "AppendedData" && !tag.closing) {
        const std::size_t underscore = text_.find('_', pos);
        if (underscore == std::string_view::npos) fail("AppendedData without its '_' marker");
        appended_base64_ = attribute(tag.attributes, "encoding") == "base64";
        appended_ = text_.substr(underscore + 1);
        if (appended_base64_) appended_ = appended_.substr(0, appended_.find('<'));
        return;  // the rest is binary
      } else if (tag.name != "DataArray" && tag.name != "InformationKey" &&
                 tag.name != "Information") {
        section = tag.closing ? std::string() : std::string(tag.name);
      }
    }
    if (!have_file_) fail("not a VTK XML file (no VTKFile element)");
  }

  /// Gives each appended array its bytes: from its offset to the next offset.
  void resolve_appended() {
    std::vector<std::size_t> offsets;
    for (const Piece& piece : pieces_) {
      for (const Array& a : piece.arrays) {
        if (a.appended) offsets.push_back(a.offset);
      }
    }
    std::sort(offsets.begin(), offsets.end());
    for (Piece& piece : pieces_) {
      for (Array& a : piece.arrays) {
        if (!a.appended) continue;
        if (a.offset > appended_.size())
          fail("DataArray '" + a.source.name + "' starts past the file's end");
        auto next = std::upper_bound(offsets.begin(), offsets.end(), a.offset);
        const std::size_t end =
            next == offsets.end() ? appended_.size() : std::min(*next, appended_.size());
        a.source.appended = appended_.substr(a.offset, end - a.offset);
        a.source.appended_base64 = appended_base64_;
      }
    }
  }

  const Array* find(const Piece& piece, std::string_view section, std::string_view name) const {
    for (const Array& a : piece.arrays) {
      if (a.section == section && (name.empty() || a.source.name == name)) return &a;
    }
    return nullptr;
  }

  std::vector<std::int64_t> ints(const Array& a, std::size_t count) const {
    std::vector<std::int64_t> v = detail::decode_ints(a.source, encoding_, file_);
    if (v.size() != count) {
      fail("DataArray '" + a.source.name + "' has " + std::to_string(v.size()) +
           " values, expected " + std::to_string(count));
    }
    return v;
  }

  /// The integer cell array giving the labels of cells of `kind` (nullptr: none).
  const Array* label_array(const Piece& piece, Kind kind) const {
    const char* own = kind == Kind::kTet        ? "subdomain"
                      : kind == Kind::kTriangle ? "patch"
                      : kind == Kind::kLine     ? "curve"
                                                : "corner";
    for (const char* name : {own, "gmsh:physical", "medit:ref", "CellEntityIds", "cell_tags",
                             "gmsh:geometrical", "MaterialIds", ""}) {
      for (const Array& a : piece.arrays) {
        if (a.section == "CellData" && a.components == 1 &&
            a.source.type.find("Int") != std::string::npos &&
            (*name == '\0' || a.source.name == name)) {
          return &a;
        }
      }
    }
    return nullptr;
  }

  void read_piece(const Piece& piece) {
    const std::size_t base = mesh_.points.size();
    if (piece.num_points > text_.size() || piece.num_cells > text_.size()) {
      fail("Piece counts exceed the file size");
    }
    const Array* points = find(piece, "Points", "");
    if (piece.num_points > 0 && points == nullptr) fail("Piece has no Points array");
    if (points != nullptr) {
      if (points->components != 3) fail("Points must have 3 components");
      const std::vector<double> xyz = detail::decode_reals(points->source, encoding_, file_);
      if (xyz.size() != 3 * piece.num_points) fail("Points has the wrong number of values");
      for (std::size_t i = 0; i < piece.num_points; ++i) {
        mesh_.points.push_back({xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
      }
    }
    if (piece.num_cells == 0) return;
    const Array* connectivity = find(piece, "Cells", "connectivity");
    const Array* offsets = find(piece, "Cells", "offsets");
    const Array* types = find(piece, "Cells", "types");
    if (!connectivity || !offsets || !types) fail("Cells lacks connectivity, offsets or types");
    const std::vector<std::int64_t> conn =
        detail::decode_ints(connectivity->source, encoding_, file_);
    const std::vector<std::int64_t> ends = ints(*offsets, piece.num_cells);
    const std::vector<std::int64_t> kinds = ints(*types, piece.num_cells);
    std::vector<std::int64_t> labels[4];
    for (Kind kind : {Kind::kPoint, Kind::kLine, Kind::kTriangle, Kind::kTet}) {
      if (const Array* a = label_array(piece, kind))
        labels[static_cast<int>(kind)] = ints(*a, piece.num_cells);
    }
    std::int64_t begin = 0;
    for (std::size_t c = 0; c < piece.num_cells; ++c) {
      if (ends[c] < begin || ends[c] > static_cast<std::int64_t>(conn.size())) {
        fail("cell " + std::to_string(c) + " has an invalid offset");
      }
      std::vector<int>& nodes = nodes_;
      nodes.clear();
      for (std::int64_t k = begin; k < ends[c]; ++k) {
        if (conn[k] < 0 || conn[k] >= static_cast<std::int64_t>(piece.num_points)) {
          fail("cell " + std::to_string(c) + " refers to point " + std::to_string(conn[k]) +
               " of " + std::to_string(piece.num_points));
        }
        nodes.push_back(static_cast<int>(base + conn[k]));
      }
      begin = ends[c];
      add_cell(kinds[c], nodes, labels, c);
    }
  }

  void add_cell(std::int64_t type, const std::vector<int>& nodes,
                const std::vector<std::int64_t> (&labels)[4], std::size_t c) {
    auto label = [&](Kind kind) {
      const auto& l = labels[static_cast<int>(kind)];
      return l.empty() ? 0 : static_cast<int>(l[c]);
    };
    auto add = [&](Kind kind, std::size_t needed, std::size_t first) {
      if (nodes.size() < first + needed) fail("cell " + std::to_string(c) + " has too few points");
      detail::add_element(mesh_, kind, nodes.data() + first, label(kind));
    };
    switch (type) {
      case 1:  // VTK_VERTEX
      case 2:  // VTK_POLY_VERTEX
        for (std::size_t i = 0; i < nodes.size(); ++i) add(Kind::kPoint, 1, i);
        break;
      case 3:   // VTK_LINE
      case 21:  // VTK_QUADRATIC_EDGE
        add(Kind::kLine, 2, 0);
        break;
      case 4:  // VTK_POLY_LINE
        for (std::size_t i = 0; i + 1 < nodes.size(); ++i) add(Kind::kLine, 2, i);
        break;
      case 5:   // VTK_TRIANGLE
      case 22:  // VTK_QUADRATIC_TRIANGLE
        add(Kind::kTriangle, 3, 0);
        break;
      case 6:  // VTK_TRIANGLE_STRIP
        for (std::size_t i = 0; i + 2 < nodes.size(); ++i) add(Kind::kTriangle, 3, i);
        break;
      case 10:  // VTK_TETRA
      case 24:  // VTK_QUADRATIC_TETRA
        add(Kind::kTet, 4, 0);
        break;
      default:
        ++mesh_.skipped_elements;
    }
  }

  std::string_view text_;
  const std::string& file_;
  bool have_file_ = false;
  detail::VtkEncoding encoding_;
  std::vector<Piece> pieces_;
  std::string_view appended_;
  bool appended_base64_ = false;
  std::vector<int> nodes_;
  ViewMesh mesh_;
};

}  // namespace

ViewMesh parse_vtu(const std::string& text, const std::string& file) {
  return VtuReader(text, file).read();
}

}  // namespace rdmesh::view
