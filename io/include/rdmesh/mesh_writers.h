// Writers for the labelled output mesh: Medit (.mesh), Gmsh 4.1 ASCII or binary
// and 2.2 ASCII (.msh) and VTK XML unstructured grid, ASCII or compressed (.vtu).
//
// Every writer emits the same information (DESIGN.md, "Contracts"):
//   - the vertices at full double precision (shortest round-trip form),
//   - each tetrahedron with its subdomain id,
//   - each boundary/interface triangle exactly once, with its patch id,
//   - each feature edge with its curve id, each corner vertex with its corner id,
//   - the subdomain, patch and curve names where the format can carry them (Gmsh,
//     VTK field data).
// A second-order mesh (rdmesh/second_order.h) is written with quadratic
// elements instead: Gmsh types 11, 9, 8; VTK types 24, 22, 21; Medit
// TetrahedraP2, TrianglesP2, EdgesP2 (node orders in io/src/element_nodes.h).
// A partitioned mesh (rdmesh/partition.h) gets Gmsh's $PartitionedEntities
// and a "partition" cell array in .vtu.
// Output is deterministic: the same TetMesh gives byte-identical files. A mesh
// without features (no edges, corner vertices, curves or corners) gives the
// same files as before the 1D/0D levels existed.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>

#include "rdmesh/atomic_file.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh {

/// Output formats chosen by file extension.
enum class MeshFormat {
  Medit,   ///< `.mesh`, MeshVersionFormatted 2
  Gmsh41,  ///< `.msh`, Gmsh MSH 4.1 (ASCII or binary)
  Vtu,     ///< `.vtu`, VTK XML UnstructuredGrid (ASCII or zlib-compressed binary arrays)
  Gmsh22,  ///< `.msh` when asked (WriteOptions::msh22), Gmsh MSH 2.2 ASCII
};

/// How write_mesh encodes the file.
enum class Encoding {
  automatic,  ///< binary above kBinaryAboveElements elements (.msh 4.1, .vtu), else ASCII
  ascii,
  binary,  ///< .msh 4.1 and .vtu only
};

/// Meshes with more elements (tetrahedra + triangles + edges + corners) than this
/// are written binary unless ASCII is asked: about 100 MB of text.
inline constexpr std::size_t kBinaryAboveElements = 1000000;

struct WriteOptions {
  Encoding encoding = Encoding::automatic;
  /// `.msh` as MSH 2.2 (ASCII) for older solvers, instead of 4.1.
  bool msh22 = false;
};

/// The format matching the extension of `path` (`.mesh`, `.msh`, `.vtu`,
/// case-insensitive).
/// @throws InputError(path, "unknown output extension ...") for any other extension.
MeshFormat format_from_path(const std::string& path);

/// Medit `.mesh`: Vertices (ref = corner id for a corner vertex, else 0),
/// Tetrahedra (ref = subdomain id), Triangles (ref = patch id), then when
/// present Edges (ref = curve id) and Corners (the corner vertices, which the
/// keyword lists without ids); 1-based indices.
/// @throws InternalError if `mesh` is inconsistent (index out of range, label
///         arrays of the wrong size, label < 1, feature edge joining a vertex to
///         itself, vertex or corner id listed twice as a corner); OutputError if
///         the stream fails.
void write_medit(const TetMesh& mesh, std::ostream& out);

/// Gmsh MSH 4.1 ASCII: one physical volume (tag = subdomain id) per subdomain,
/// one physical surface (tag = patch id) per patch, one physical curve (tag =
/// curve id) per curve and one physical point (tag = corner id) per corner, all
/// named ("corner_<id>" for corners, which have no name); one elementary entity
/// per physical group with the same tag. Entity topology: a volume is bounded
/// by the patches of TetMesh::patches touching it, a surface by the curves whose
/// CurveInfo::patches list it, an open curve by its start (+) and end (-) corner.
/// All nodes are written in a single block classified on the first volume
/// entity; elements are grouped by entity (type 4 tetrahedra, type 2 triangles,
/// type 1 lines, type 15 points, in that order). Node and element tags are 1-based.
/// @throws InternalError if `mesh` is inconsistent; OutputError if the stream fails.
void write_gmsh41(const TetMesh& mesh, std::ostream& out);
/// The same in MSH 4.1 binary ("4.1 1 8"): the $Entities, $Nodes and $Elements
/// data as Gmsh's binary layout (int 4 bytes, size_t 8, double 8).
void write_gmsh41_binary(const TetMesh& mesh, std::ostream& out);

/// Gmsh MSH 2.2 ASCII, for older solvers: $PhysicalNames as in 4.1, all nodes,
/// then the elements (tetrahedra, triangles, lines, points, as in 4.1) each with
/// two tags, its physical group and its elementary entity (the same id).
/// @throws InternalError if `mesh` is inconsistent; OutputError if the stream fails.
void write_gmsh22(const TetMesh& mesh, std::ostream& out);

/// VTK XML `.vtu` with tetrahedra (VTK type 10), then triangles (type 5), then
/// feature edges (type 3, VTK_LINE) and corner vertices (type 1, VTK_VERTEX) in
/// one UnstructuredGrid. Int32 cell arrays: "subdomain" (0 except on
/// tetrahedra) and "patch" (0 except on triangles); for a mesh with features
/// also "curve" (0 except on lines) and "corner" (0 except on vertices).
/// Indices are 0-based as VTK requires.
/// @throws InternalError if `mesh` is inconsistent; OutputError if the stream fails.
void write_vtu(const TetMesh& mesh, std::ostream& out);
/// The same with binary arrays, zlib-compressed and base64-encoded inline
/// (compressor="vtkZLibDataCompressor", as VTK writes them). Both carry the
/// names of subdomains, patches and curves as field data: one Int32 array per
/// name, its id and dimension (meshio's field_data).
void write_vtu_binary(const TetMesh& mesh, std::ostream& out);

/// Writes `mesh` to `path` in the format given by its extension.
/// The data goes to a fresh temporary file `path.tmp-XXXXXX` in the same
/// directory, which is then renamed over `path` (atomic on POSIX): `path` is
/// either left untouched or fully replaced, and no temporary file is left behind.
/// @throws InputError for an unknown extension (nothing is created);
///         OutputError("path: problem") when the file cannot be created,
///         written or renamed (e.g. missing or read-only directory);
///         InternalError if `mesh` is inconsistent (the temporary file is removed).
void write_mesh(const TetMesh& mesh, const std::string& path, const WriteOptions& options = {});
/// write_mesh without its last step: the file is written and flushed under
/// its temporary name, and replaces `path` when the result is committed
/// (dropped uncommitted, it is removed). Throws what write_mesh throws.
StagedFile stage_mesh(const TetMesh& mesh, const std::string& path,
                      const WriteOptions& options = {});

/// Whether write_mesh writes `mesh` to a file of `format` in binary.
/// @throws InputError when `options` ask what the format cannot do (binary Medit
///         or MSH 2.2, MSH 2.2 in another format).
bool writes_binary(const TetMesh& mesh, MeshFormat format, const WriteOptions& options);

}  // namespace rdmesh
