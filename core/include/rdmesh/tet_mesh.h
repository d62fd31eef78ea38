// The labelled output of rdmesh: a tetrahedral mesh with its restricted
// surface triangles. Plain arrays so that writers and tests need no CGAL.
#pragma once

#include <array>
#include <vector>

#include "rdmesh/geometry.h"
#include "rdmesh/oracle.h"

namespace rdmesh {

/// The vertex pairs of a tetrahedron's edges in the order of TetMesh::tet_mid_nodes.
inline constexpr std::array<std::array<int, 2>, 6> kTetEdges{
    {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}}};
/// The vertex pairs of a triangle's edges in the order of TetMesh::triangle_mid_nodes.
inline constexpr std::array<std::array<int, 2>, 3> kTriangleEdges{{{0, 1}, {1, 2}, {2, 0}}};

struct TetMesh {
  /// Vertex coordinates; every vertex is used by at least one element.
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

  /// Second-order nodes (rdmesh/second_order.h); all three empty for a
  /// first-order mesh. The mid-edge nodes are vertices too, numbered after the
  /// first-order ones. tet_mid_nodes[t][k] is the node on edge kTetEdges[k] of
  /// tets[t] (Gmsh's order: 01, 12, 20, 30, 32, 31); triangle_mid_nodes[f] the
  /// nodes on edges 01, 12, 20 of triangles[f]; edge_mid_nodes[e] the node of
  /// edges[e].
  std::vector<std::array<int, 6>> tet_mid_nodes;
  std::vector<std::array<int, 3>> triangle_mid_nodes;
  std::vector<int> edge_mid_nodes;

  /// Partitions (rdmesh/partition.h), 1..n, one per element; all four empty
  /// for a mesh that is not partitioned.
  std::vector<int> tet_partition, triangle_partition, edge_partition, corner_partition;

  /// Names and ids of the domain's features (copied from the oracle).
  std::vector<SubdomainInfo> subdomains;
  std::vector<PatchInfo> patches;
  std::vector<CurveInfo> curves;
  std::vector<CornerInfo> corners;
};

}  // namespace rdmesh
