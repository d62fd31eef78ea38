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

  /// Names and ids of the domain's subdomains and patches (copied from the oracle).
  std::vector<SubdomainInfo> subdomains;
  std::vector<PatchInfo> patches;
};

}  // namespace rdmesh
