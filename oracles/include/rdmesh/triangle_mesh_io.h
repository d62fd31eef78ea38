// Reading triangle meshes: OFF, STL (ASCII and binary), OBJ and PLY (ASCII and binary).
//
// Every reader returns a TriangleSoup whose duplicate vertices (exactly equal
// coordinates, as STL writes one copy per facet) are merged, polygons with more
// than three corners fan-triangulated from their first corner, and every index
// checked. Errors are InputError "FILE: problem" (line numbers where the format
// has lines). Structural checks of the surface (closed, manifold, oriented, free
// of self-intersections) are those of rdmesh/triangle_mesh_check.h.
#pragma once

#include <array>
#include <istream>
#include <string>
#include <vector>

#include "rdmesh/geometry.h"

namespace rdmesh {

/// Vertices and triangles (indices into `points`, 0-based) of a triangle mesh.
struct TriangleSoup {
  std::vector<Point3> points;
  std::vector<std::array<int, 3>> triangles;
};

/// Reads `path`, choosing the format by its extension (.off, .stl, .obj, .ply,
/// case-insensitive), then merges duplicate vertices and validates indices and
/// coordinates (validate_soup). Throws InputError for an unreadable file, an
/// unknown extension or any problem of the content.
TriangleSoup read_triangle_mesh(const std::string& path);

/// Parses OFF text (optional "OFF" header, `#` comments, polygon faces).
/// `file` names the input in error messages.
TriangleSoup parse_off(std::istream& in, const std::string& file);

/// Parses STL: binary when the byte count matches 84 + 50 * (triangle count in
/// the header), ASCII when the text starts with "solid" and is not such a binary
/// file; otherwise a truncated or oversized binary file (InputError).
TriangleSoup parse_stl(std::istream& in, const std::string& file);

/// Parses Wavefront OBJ: `v x y z [w]` and `f i[/t][/n] ...` lines (negative
/// indices are relative to the end), every other statement ignored.
TriangleSoup parse_obj(std::istream& in, const std::string& file);

/// Parses PLY (ascii, binary_little_endian, binary_big_endian): the `vertex`
/// element's x, y, z properties and the `face` element's `vertex_indices` (or
/// `vertex_index`) list; other elements and properties are skipped.
TriangleSoup parse_ply(std::istream& in, const std::string& file);

/// Merges vertices with exactly equal coordinates (first occurrence kept, order
/// preserved) and drops vertices no triangle uses; triangles are renumbered.
void merge_duplicate_vertices(TriangleSoup& soup);

/// Throws InputError "FILE: problem" for: no triangle, a non-finite coordinate,
/// an index out of range, a triangle with a repeated vertex (after merging) or
/// with collinear corners (exact predicate), and coordinates too large (above
/// 1e100 in magnitude) for the geometric computations.
void validate_soup(const TriangleSoup& soup, const std::string& file);

}  // namespace rdmesh
