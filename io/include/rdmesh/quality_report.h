// The quality report of an output mesh (DESIGN.md, "Contracts"): counts per
// subdomain and patch, dihedral angle extremes and histogram, radius-edge
// ratio, volumes, boundary topology and the measured distance of boundary
// triangles to their patch; for sharp features, per-curve edge counts, chain
// topology and distance to the curve, and the corners found.
#pragma once

#include <array>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rdmesh/mesh_measures.h"
#include "rdmesh/oracle.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh {

/// Per-subdomain figures.
struct SubdomainStats {
  SubdomainId id;
  std::string name;      ///< from TetMesh::subdomains, empty if the id is not listed there
  std::size_t tets = 0;  ///< tetrahedra labelled `id`
  double volume = 0;     ///< sum of their signed volumes
};

/// Per-patch figures.
struct PatchStats {
  PatchId id;
  std::string name;              ///< from TetMesh::patches, empty if the id is not listed there
  std::size_t triangles = 0;     ///< triangles labelled `id`
  double area = 0;               ///< their total area
  int euler_characteristic = 0;  ///< V - E + F of those triangles
  double max_distance = -1;      ///< max sampled distance to the patch; -1 = not measured
  std::size_t projection_failures = 0;  ///< samples whose projection failed (skipped)
};

/// Per-curve figures.
struct CurveStats {
  CurveId id;
  std::string name;       ///< from TetMesh::curves, empty if the id is not listed there
  std::size_t edges = 0;  ///< feature edges labelled `id`
  /// The curve's edges form one simple chain (is_simple_chain): an open path
  /// whose two ends are the vertices of its start and end corners, or one
  /// cycle when the curve is closed (a cycle through the corner when an open
  /// curve starts and ends at the same corner). A curve not listed in
  /// TetMesh::curves passes with either shape. Orientation is not checked.
  bool is_chain = false;
  /// Max distance of the edge samples (vertices, midpoints, quarter points) to
  /// the curve, the closest point being oracle->curve(id).point(closest(sample,
  /// t_begin, t_end)); -1 = not measured (no oracle, or every sample failed).
  double max_distance = -1;
  std::size_t projection_failures = 0;  ///< samples whose closest-point query failed (skipped)
};

/// Whole-mesh figures. Every patch and subdomain listed in the TetMesh appears,
/// plus any id used by an element but missing from the lists; both sorted by id.
struct QualityReport {
  std::size_t vertices = 0, tets = 0, triangles = 0;
  double min_dihedral_deg = 0;  ///< over all tets (0 when there is none)
  double max_dihedral_deg = 0;  ///< over all tets (0 when there is none)
  double max_radius_edge = 0;   ///< circumradius / shortest edge; +inf if a tet is flat
  /// Number of tets whose minimum dihedral angle lies in [5i, 5i+5) degrees.
  /// Sums to `tets`.
  std::array<std::size_t, 36> dihedral_histogram{};
  std::size_t inverted_tets = 0;          ///< tets with signed volume <= 0 (should be 0)
  double boundary_max_distance = -1;      ///< max over patches; -1 = not measured
  int boundary_euler_characteristic = 0;  ///< of the union of all boundary triangles
  std::size_t projection_failures = 0;    ///< sum over patches
  std::vector<SubdomainStats> subdomains;
  std::vector<PatchStats> patches;
  /// Every curve listed in TetMesh::curves or used by a feature edge, sorted by id.
  std::vector<CurveStats> curves;
  std::size_t corners_present = 0;   ///< corners of TetMesh::corners that have a corner vertex
  std::size_t corners_expected = 0;  ///< TetMesh::corners.size()
  double feature_max_distance = -1;  ///< max over curves; -1 = not measured
};

/// Measures `mesh`. When `oracle` is not null, each boundary triangle is
/// sampled at its vertices, edge midpoints and centroid, and the distance of
/// each sample to oracle->project(sample, patch) is taken; samples shared by
/// neighbouring triangles of the same patch are projected once. Samples whose
/// projection returns nullopt or throws OracleError are skipped and counted in
/// `projection_failures`. With a null oracle no distance is measured (-1).
/// `threads` (0: all cores) share the per-tet figures, which are the same for
/// any thread count; the oracle is called from the calling thread only.
/// @throws InternalError if `mesh` is inconsistent (index out of range, label
///         arrays of the wrong size).
QualityReport measure_quality(const TetMesh& mesh, const DomainOracle* oracle, int threads = 1);

/// The report as JSON. Keys are the field names of QualityReport,
/// SubdomainStats, PatchStats and CurveStats; ids are plain integers; a non-finite value
/// (radius-edge of a flat tet) is written as null.
nlohmann::json to_json(const QualityReport& r);

/// A human-readable multi-line summary (global figures, then one table row per
/// subdomain and per patch; a features line when the mesh has curves or
/// corners, and one row per curve when it has curves) for the terminal. Ends
/// with a newline.
std::string format_summary(const QualityReport& r);

}  // namespace rdmesh
