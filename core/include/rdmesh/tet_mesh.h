// The labelled output of rdmesh: a tetrahedral mesh with its restricted
// surface triangles. Plain arrays so that writers and tests need no CGAL.
#pragma once

#include <array>
#include <vector>

#include "rdmesh/geometry.h"
#include "rdmesh/oracle.h"

namespace rdmesh {

struct TetMesh {
  /// Vertex coordinates; every vertex is used by at least one tetrahedron.
  std::vector<Point3> vertices;

  /// Tetrahedra (0-based vertex indices), positively oriented:
  /// dot(v1 - v0, cross(v2 - v0, v3 - v0)) > 0.
  std::vector<std::array<int, 4>> tets;
  /// Subdomain of each tetrahedron (never kOutside).
  std::vector<SubdomainId> tet_subdomain;

  /// Boundary and interface triangles, each written once (the restricted
  /// facets D|S_k). Oriented so that the normal (v1-v0) x (v2-v0) points
  /// towards the side with the smaller subdomain id (outward on the outer boundary).
  std::vector<std::array<int, 3>> triangles;
  /// Patch of each triangle.
  std::vector<PatchId> triangle_patch;

  /// Feature edges (the restricted edges D|L_j), each written once, oriented
  /// along increasing curve parameter. Both vertices are mesh vertices.
  std::vector<std::array<int, 2>> edges;
  /// Curve of each feature edge.
  std::vector<CurveId> edge_curve;

  /// Mesh vertices that are corners of the input (Q), and the corner each one is.
  std::vector<int> corner_vertices;
  std::vector<CornerId> corner_ids;

  /// Names and ids of the domain's features (copied from the oracle).
  std::vector<SubdomainInfo> subdomains;
  std::vector<PatchInfo> patches;
  std::vector<CurveInfo> curves;
  std::vector<CornerInfo> corners;
};

}  // namespace rdmesh
