// Internal to io/: the partition-boundary entities that Gmsh creates with
// Mesh.PartitionCreateTopology (its default) and writes in a partitioned
// .msh 4.1 file, computed from a partitioned TetMesh.
//
// - Surfaces: the faces shared by two tetrahedra of different partitions that
//   are not triangles of the model, one entity per (subdomain, partition
//   pair), child of that subdomain.
// - Curves: the edges, not feature edges, where faces of different entities
//   meet (partitioned patches and partition-boundary surfaces), one entity per
//   (parent, partitions): the union of the partitions of those faces; the
//   parent is the patch the edge lies on, else the subdomain.
// - Points: the vertices, not corners, where edges of different entities meet
//   (partitioned curves and partition-boundary curves), one entity per
//   (parent, partitions); the parent is the curve, else the patch, else the
//   subdomain the vertex lies on.
// Each entity is split into its connected pieces, as Gmsh does: faces
// sharing an edge, lines sharing a vertex that is not a point or a corner
// (curves end at points); one point entity per vertex.
// Entities come in ascending (parent dimension, parent, partitions) order,
// elements in ascending vertex order: the same mesh gives the same entities.
#pragma once

#include <array>
#include <vector>

#include "rdmesh/tet_mesh.h"

namespace rdmesh::io_detail {

struct PartitionBoundary {
  int parent_dim = 0, parent = 0;
  std::vector<int> partitions;  ///< ascending, at least two
  /// Node indices per element in Gmsh's order: the vertices, then (second
  /// order) the mid-edge nodes of edges 01, 12, 20 (triangles) or 01 (lines).
  std::vector<std::vector<int>> elements;
};

/// Indexed by dimension: [0] points, [1] curves, [2] surfaces ([3] empty).
using PartitionBoundaries = std::array<std::vector<PartitionBoundary>, 4>;

/// The partition-boundary entities of a partitioned mesh (TetMesh::tet_partition
/// and the other partition arrays filled); empty for a mesh with one partition.
PartitionBoundaries partition_boundaries(const TetMesh& mesh);

}  // namespace rdmesh::io_detail
