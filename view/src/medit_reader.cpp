// Medit .mesh ASCII reader (MeshVersionFormatted 1 or 2, Dimension 3).
//
// Keeps Vertices, Tetrahedra (ref = subdomain), Triangles (ref = patch), Edges
// (ref = curve) and Corners, plus the corners of the P2 elements; skips the
// other sections of the format whose record size is known (quadrangles,
// hexahedra, prisms, normals, tangents, required entities, ...) and rejects
// any other keyword, since its records could not be skipped safely.
#include <array>
#include <string>
#include <string_view>

#include "element_kinds.h"
#include "rdmesh/view_mesh.h"
#include "text_scanner.h"

namespace rdmesh::view {
namespace {

using detail::Kind;

struct Section {
  const char* keyword;   ///< lower case
  int ints;              ///< integers per record (indices, then the reference if any)
  int reals;             ///< reals per record, read before the integers (vertices only)
  Kind kind;             ///< what the first indices make; kOther: not drawn
  int corners;           ///< corner indices per record of a drawn element
  bool element = false;  ///< an element the picture skips (counted)
};

// Records are "reals..., ints...". Element records end with their reference.
constexpr Section kSections[] = {
    {"vertices", 1, 3, Kind::kOther, 0},
    {"tetrahedra", 5, 0, Kind::kTet, 4},
    {"triangles", 4, 0, Kind::kTriangle, 3},
    {"edges", 3, 0, Kind::kLine, 2},
    {"corners", 1, 0, Kind::kPoint, 1},
    {"tetrahedrap2", 11, 0, Kind::kTet, 4},
    {"trianglesp2", 7, 0, Kind::kTriangle, 3},
    {"edgesp2", 4, 0, Kind::kLine, 2},
    {"quadrilaterals", 5, 0, Kind::kOther, 0, true},
    {"hexahedra", 9, 0, Kind::kOther, 0, true},
    {"prisms", 7, 0, Kind::kOther, 0, true},
    {"pyramids", 6, 0, Kind::kOther, 0, true},
    {"ridges", 1, 0, Kind::kOther, 0},
    {"requiredvertices", 1, 0, Kind::kOther, 0},
    {"requirededges", 1, 0, Kind::kOther, 0},
    {"requiredtriangles", 1, 0, Kind::kOther, 0},
    {"requiredquadrilaterals", 1, 0, Kind::kOther, 0},
    {"normals", 0, 3, Kind::kOther, 0},
    {"tangents", 0, 3, Kind::kOther, 0},
    {"normalatvertices", 2, 0, Kind::kOther, 0},
    {"normalattrianglevertices", 3, 0, Kind::kOther, 0},
    {"tangentatvertices", 2, 0, Kind::kOther, 0},
    {"tangentatedges", 3, 0, Kind::kOther, 0},
};

const Section* find_section(std::string_view keyword) {
  const std::string key = detail::lower(keyword);
  for (const Section& s : kSections) {
    if (key == s.keyword) return &s;
  }
  return nullptr;
}

void read_section(detail::TextScanner& s, const Section& section, ViewMesh& mesh) {
  const std::size_t n = s.read_count("the number of records",
                                     2 * static_cast<std::size_t>(section.ints + section.reals));
  const bool vertices = std::string_view(section.keyword) == "vertices";
  if (vertices) mesh.points.reserve(mesh.points.size() + n);
  for (std::size_t i = 0; i < n; ++i) {
    double reals[3];
    for (int k = 0; k < section.reals; ++k) reals[k] = s.read_double("a coordinate");
    std::array<long long, 11> ints{};
    for (int k = 0; k < section.ints; ++k) ints[k] = s.read_int("an index or reference");
    if (vertices) {
      mesh.points.push_back({reals[0], reals[1], reals[2]});
    } else if (section.kind != Kind::kOther) {
      int nodes[4];
      for (int k = 0; k < section.corners; ++k) {
        // 1-based; anything out of range is reported by check_view_mesh.
        nodes[k] = ints[k] >= 1 && ints[k] <= 2147483647 ? static_cast<int>(ints[k] - 1) : -1;
      }
      const long long ref = section.kind == Kind::kPoint ? 0 : ints[section.ints - 1];
      detail::add_element(mesh, section.kind, nodes, static_cast<int>(ref));
    } else if (section.element) {
      ++mesh.skipped_elements;
    }
  }
}

}  // namespace

ViewMesh parse_medit(const std::string& text, const std::string& file) {
  detail::TextScanner s(text, file, '#');
  ViewMesh mesh;
  if (detail::lower(s.next()) != "meshversionformatted") {
    s.fail("not a Medit ASCII mesh (no MeshVersionFormatted)");
  }
  s.read_int("the format version", 1, 4);
  bool have_dimension = false;
  for (std::string_view keyword = s.next(); detail::lower(keyword) != "end"; keyword = s.next()) {
    if (keyword.empty()) break;  // End is optional
    if (detail::lower(keyword) == "dimension") {
      if (s.read_int("the dimension") != 3) s.fail("only 3D meshes (Dimension 3) are supported");
      have_dimension = true;
      continue;
    }
    const Section* section = find_section(keyword);
    if (section == nullptr) s.fail("unknown keyword '" + std::string(keyword) + "'");
    if (!have_dimension) s.fail("Dimension missing before " + std::string(keyword));
    read_section(s, *section, mesh);
  }
  return mesh;
}

}  // namespace rdmesh::view
