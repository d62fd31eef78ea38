// Internal helpers shared by the writers and the quality report: mesh
// validation, the sorted list of labels with their names, number formatting.
#pragma once

#include <charconv>
#include <locale>
#include <ostream>
#include <string>
#include <vector>

#include "rdmesh/tet_mesh.h"

namespace rdmesh::io_detail {

/// Throws InternalError unless the label arrays match the element arrays,
/// every label is >= 1, every coordinate is finite, every element index
/// refers to an existing vertex, no feature edge joins a vertex to itself and
/// no vertex or corner id appears twice in the corner lists.
void check_mesh(const TetMesh& mesh);

/// True when the mesh has any 1D or 0D data (feature edges, corner vertices,
/// listed curves or corners); writers emit the feature sections only then.
bool has_features(const TetMesh& mesh);

/// A label (subdomain or patch id) with its name.
struct Label {
  int id = 0;
  std::string name;  ///< empty when the TetMesh lists no name for this id
};

/// Subdomains listed in mesh.subdomains plus those used by a tet, sorted by id,
/// without duplicates.
std::vector<Label> subdomain_labels(const TetMesh& mesh);

/// Patches listed in mesh.patches plus those used by a triangle, sorted by id.
std::vector<Label> patch_labels(const TetMesh& mesh);

/// Curves listed in mesh.curves plus those used by a feature edge, sorted by id.
std::vector<Label> curve_labels(const TetMesh& mesh);

/// Corners listed in mesh.corners plus those of corner_vertices, sorted by id
/// (names are empty: corners have none).
std::vector<Label> corner_labels(const TetMesh& mesh);

/// Element indices grouped by label: result[k] lists the elements whose label
/// is labels[k].id, in input order.
std::vector<std::vector<int>> group_by_label(const std::vector<int>& element_labels,
                                             const std::vector<Label>& labels);

/// The subdomain ids of the tets / patch ids of the triangles as plain ints.
std::vector<int> tet_label_values(const TetMesh& mesh);
std::vector<int> triangle_label_values(const TetMesh& mesh);
/// The curve ids of the feature edges / corner ids of the corner vertices as plain ints.
std::vector<int> edge_label_values(const TetMesh& mesh);
std::vector<int> corner_label_values(const TetMesh& mesh);

/// The name written for a label of dimension `dim` (3 subdomain ... 0 corner): its
/// own, else "subdomain_<id>", "patch_<id>", "curve_<id>" or "corner_<id>".
inline std::string physical_name(const Label& label, int dim) {
  static const char* const kPrefixes[4] = {"corner_", "curve_", "patch_", "subdomain_"};
  return label.name.empty() ? kPrefixes[dim] + std::to_string(label.id) : label.name;
}

/// physical_name() in double quotes, as Gmsh's $PhysicalNames wants it: quotes
/// inside become single quotes, newlines spaces.
inline std::string quoted_physical_name(const Label& label, int dim) {
  std::string name = physical_name(label, dim);
  for (char& c : name) {
    if (c == '"') c = '\'';
    if (c == '\n') c = ' ';
  }
  return '"' + name + '"';
}

/// Appends `v` in the shortest form that reads back to the same double.
inline void append_double(std::string& s, double v) {
  char buf[32];
  auto res = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, static_cast<std::size_t>(res.ptr - buf));
}

/// While alive, `out` writes numbers in the "C" form (no thousands grouping,
/// a point for decimals) whatever locale the caller gave it; the caller's
/// locale comes back at the end. For writers that put numbers through `<<`.
class ClassicLocale {
 public:
  explicit ClassicLocale(std::ostream& out)
      : out_(out), before_(out.imbue(std::locale::classic())) {}
  ClassicLocale(const ClassicLocale&) = delete;
  ClassicLocale& operator=(const ClassicLocale&) = delete;
  ~ClassicLocale() { out_.imbue(before_); }

 private:
  std::ostream& out_;
  std::locale before_;
};

/// Appends an integer in decimal.
inline void append_int(std::string& s, long long v) {
  char buf[24];
  auto res = std::to_chars(buf, buf + sizeof buf, v);
  s.append(buf, static_cast<std::size_t>(res.ptr - buf));
}

}  // namespace rdmesh::io_detail
