// The PLY reader (ascii, binary_little_endian, binary_big_endian).
//
// The header declares elements in file order, each with scalar properties and
// list properties (a count then that many items). Only vertex x, y, z and the
// face's vertex_indices (or vertex_index) list are kept; every other element and
// property is read and discarded, so files with normals, colours or extra
// elements load.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "rdmesh/errors.h"
#include "rdmesh/triangle_mesh_io.h"
#include "triangle_mesh_text.h"

namespace rdmesh {
namespace {

enum class Type { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

struct Property {
  std::string name;
  Type type = Type::kFloat32;
  bool is_list = false;
  Type count_type = Type::kUint8;
};

struct Element {
  std::string name;
  long long count = 0;
  std::vector<Property> properties;
};

int size_of(Type t) {
  switch (t) {
    case Type::kInt8:
    case Type::kUint8:
      return 1;
    case Type::kInt16:
    case Type::kUint16:
      return 2;
    case Type::kInt32:
    case Type::kUint32:
    case Type::kFloat32:
      return 4;
    case Type::kFloat64:
      return 8;
  }
  return 0;
}

Type parse_type(std::string_view s, const LineReader& r) {
  if (s == "char" || s == "int8") return Type::kInt8;
  if (s == "uchar" || s == "uint8") return Type::kUint8;
  if (s == "short" || s == "int16") return Type::kInt16;
  if (s == "ushort" || s == "uint16") return Type::kUint16;
  if (s == "int" || s == "int32") return Type::kInt32;
  if (s == "uint" || s == "uint32") return Type::kUint32;
  if (s == "float" || s == "float32") return Type::kFloat32;
  if (s == "double" || s == "float64") return Type::kFloat64;
  r.fail("unknown PLY type '" + std::string(s) + "'");
}

/// Reads values from the body: tokens of text lines, or bytes of a binary body.
class BodyReader {
 public:
  BodyReader(LineReader& r, const std::string& file, int format)
      : r_(r), file_(file), format_(format) {}

  double value(Type t) {
    if (format_ == 0) {
      while (next_ >= tokens_.size()) {
        if (!r_.next(tokens_)) throw InputError(file_, "PLY body ends early");
        next_ = 0;
      }
      return r_.real(tokens_[next_++]);
    }
    unsigned char b[8];
    const int n = size_of(t);
    if (!r_.stream().read(reinterpret_cast<char*>(b), n)) {
      throw InputError(file_, "binary PLY body ends early (truncated file)");
    }
    if ((format_ == 2) != (std::endian::native == std::endian::big)) std::reverse(b, b + n);
    return decode(t, b);
  }

 private:
  static double decode(Type t, const unsigned char* b) {
    auto as = [b](auto v) {
      std::memcpy(&v, b, sizeof v);
      return static_cast<double>(v);
    };
    switch (t) {
      case Type::kInt8:
        return as(std::int8_t{});
      case Type::kUint8:
        return as(std::uint8_t{});
      case Type::kInt16:
        return as(std::int16_t{});
      case Type::kUint16:
        return as(std::uint16_t{});
      case Type::kInt32:
        return as(std::int32_t{});
      case Type::kUint32:
        return as(std::uint32_t{});
      case Type::kFloat32:
        return as(float{});
      case Type::kFloat64:
        return as(double{});
    }
    return 0;
  }

  LineReader& r_;
  std::string file_;
  int format_;  // 0 ascii, 1 little endian, 2 big endian
  std::vector<std::string_view> tokens_;
  std::size_t next_ = 0;
};

/// Bytes left in `in` after its current position; -1 when the stream cannot tell.
long long remaining_bytes(std::istream& in) {
  const std::istream::pos_type here = in.tellg();
  if (here == std::istream::pos_type(-1)) return -1;
  in.seekg(0, std::ios::end);
  const std::istream::pos_type end = in.tellg();
  in.seekg(here);
  if (end == std::istream::pos_type(-1) || !in) {
    in.clear();
    in.seekg(here);
    return -1;
  }
  return static_cast<long long>(end - here);
}

/// Refuses, before anything is allocated, element counts the rest of the file cannot
/// hold: an element takes at least its scalar sizes plus its lists' count sizes in a
/// binary body, and at least 2 bytes (a digit and a separator) per property in an
/// ASCII one (the last may lack its separator). An element without properties is refused unless its
/// count is 0.
void check_counts(const std::vector<Element>& elements, int format, long long remaining,
                  const std::string& file) {
  long double need = 0;
  for (const Element& e : elements) {
    if (e.count > 0 && e.properties.empty()) {
      throw InputError(file, "PLY element '" + e.name + "' declares " + std::to_string(e.count) +
                                 " items but no property");
    }
    long long bytes = 0;
    for (const Property& p : e.properties) {
      bytes += format == 0 ? 2 : size_of(p.is_list ? p.count_type : p.type);
    }
    need += static_cast<long double>(bytes) * e.count;
    if (remaining >= 0 && need > remaining + (format == 0 ? 1 : 0)) {  // ASCII: no final newline
      throw InputError(file, "PLY header declares " + std::to_string(e.count) + " '" + e.name +
                                 "' items, but the file ends early: the " +
                                 std::to_string(remaining) +
                                 " bytes after the header cannot hold them");
    }
  }
}

}  // namespace

TriangleSoup parse_ply(std::istream& in, const std::string& file) {
  LineReader r(in, file);
  std::vector<std::string_view> tok;
  if (!r.next(tok) || tok[0] != "ply") throw InputError(file, "not a PLY file (no 'ply' line)");
  int format = -1;
  std::vector<Element> elements;
  for (;;) {
    if (!r.next(tok)) throw InputError(file, "PLY header without 'end_header'");
    if (tok[0] == "end_header") break;
    if (tok[0] == "comment" || tok[0] == "obj_info") continue;
    if (tok[0] == "format") {
      if (tok.size() < 2) r.fail("'format' needs a value");
      if (tok[1] == "ascii") format = 0;
      if (tok[1] == "binary_little_endian") format = 1;
      if (tok[1] == "binary_big_endian") format = 2;
      if (format < 0) r.fail("unknown PLY format '" + std::string(tok[1]) + "'");
    } else if (tok[0] == "element") {
      if (tok.size() != 3) r.fail("'element' needs a name and a count");
      elements.push_back({std::string(tok[1]), r.integer(tok[2]), {}});
      if (elements.back().count < 0) r.fail("negative element count");
    } else if (tok[0] == "property") {
      if (elements.empty()) r.fail("'property' before any 'element'");
      Property p;
      if (tok.size() == 5 && tok[1] == "list") {
        p = {std::string(tok[4]), parse_type(tok[3], r), true, parse_type(tok[2], r)};
      } else if (tok.size() == 3) {
        p = {std::string(tok[2]), parse_type(tok[1], r), false, Type::kUint8};
      } else {
        r.fail("malformed 'property' line");
      }
      elements.back().properties.push_back(p);
    } else {
      r.fail("unexpected '" + std::string(tok[0]) + "' in the PLY header");
    }
  }
  if (format < 0) throw InputError(file, "PLY header without 'format'");
  check_counts(elements, format, remaining_bytes(r.stream()), file);
  TriangleSoup soup;
  BodyReader body(r, file, format);
  std::vector<long long> ids;
  for (const Element& e : elements) {
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    for (long long i = 0; i < e.count; ++i) {
      Point3 p;
      ids.clear();
      for (const Property& prop : e.properties) {
        if (prop.is_list) {
          const double n = body.value(prop.count_type);
          // Checked before any cast: NaN or 1e30 as a long long is undefined.
          if (!(n >= 0 && n <= 1e15) || n != std::floor(n)) {
            throw InputError(file, "bad list length in element '" + e.name + "'");
          }
          const bool keep =
              is_face && (prop.name == "vertex_indices" || prop.name == "vertex_index");
          for (long long k = 0; k < static_cast<long long>(n); ++k) {
            const double v = body.value(prop.type);
            if (keep && !(std::fabs(v) < 1e18)) {
              throw InputError(file, "bad vertex index in element '" + e.name + "'");
            }
            if (keep) ids.push_back(static_cast<long long>(v));
          }
        } else {
          const double v = body.value(prop.type);
          if (is_vertex && prop.name == "x") p.x = v;
          if (is_vertex && prop.name == "y") p.y = v;
          if (is_vertex && prop.name == "z") p.z = v;
        }
      }
      if (is_vertex) soup.points.push_back(p);
      if (!is_face) continue;
      if (ids.size() < 3)
        throw InputError(file, "face " + std::to_string(i) + " has fewer than 3 vertices");
      for (long long id : ids) {
        if (id < 0 || id >= static_cast<long long>(soup.points.size())) {
          throw InputError(file, "face " + std::to_string(i) + ": vertex index " +
                                     std::to_string(id) + " out of range [0, " +
                                     std::to_string(soup.points.size()) + ")");
        }
      }
      for (std::size_t k = 1; k + 1 < ids.size(); ++k) {
        soup.triangles.push_back(
            {static_cast<int>(ids[0]), static_cast<int>(ids[k]), static_cast<int>(ids[k + 1])});
      }
    }
  }
  return soup;
}

}  // namespace rdmesh
