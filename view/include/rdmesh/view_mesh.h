// The mesh as the picture sees it: plain arrays of points and labelled
// elements, read from a file (.msh, .mesh, .vtu) or converted from a TetMesh.
//
// view/ depends on nothing of the mesher: a mesh written by rdmesh, Gmsh,
// TetGen or meshio is drawn the same way. Labels are whatever the file says
// (a Gmsh physical tag, a Medit reference, a VTK cell array); the picture only
// needs them to tell elements apart.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "rdmesh/geometry.h"

namespace rdmesh::view {

struct ViewMesh {
  std::vector<Point3> points;

  /// Tetrahedra (0-based point indices, either orientation) and their subdomain.
  std::vector<std::array<int, 4>> tets;
  std::vector<int> tet_labels;

  /// Boundary and interface triangles and their patch.
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> triangle_labels;

  /// Feature edges (sharp curves) and their curve.
  std::vector<std::array<int, 2>> edges;
  std::vector<int> edge_labels;

  /// Corner points (indices into `points`).
  std::vector<int> corners;

  /// Names of subdomains by label, where the file gives them (Gmsh physical names).
  std::map<int, std::string> subdomain_names;

  /// Elements of the file the picture does not draw (quadrangles, hexahedra, prisms,
  /// pyramids, polygons); the legend mentions them.
  std::size_t skipped_elements = 0;
};

/// Checks what the picture relies on: label arrays as long as their elements,
/// every index within `points`, finite coordinates.
/// @throws InputError(file, problem) naming the first offending element.
void check_view_mesh(const ViewMesh& mesh, const std::string& file);

/// Reads a mesh file, choosing the reader by extension (case-insensitive):
/// `.msh` Gmsh ASCII 4.1 or 2.2, `.mesh` Medit ASCII, `.vtu` VTK XML (ascii,
/// inline base64 binary, zlib-compressed or not, and appended data). Files of
/// any origin are accepted; counts are checked against the file size before
/// anything is allocated, so a corrupt or hostile file is an error, never a
/// crash or a huge allocation.
/// @throws InputError("path: problem") for an unreadable, malformed or
///         unsupported file, or one with neither tetrahedra nor triangles.
ViewMesh read_view_mesh(const std::string& path);

/// The readers on text already in memory; `file` names it in error messages.
ViewMesh parse_gmsh(const std::string& text, const std::string& file);
ViewMesh parse_medit(const std::string& text, const std::string& file);
ViewMesh parse_vtu(const std::string& text, const std::string& file);

}  // namespace rdmesh::view
