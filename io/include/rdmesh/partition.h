// Partitions of a tetrahedral mesh for parallel solvers: METIS (k-way) on the
// tetrahedra's dual graph, whose edges join tetrahedra sharing a face
// (interface faces between subdomains included). METIS is asked for 1%
// balance; when k-way leaves a part more than 3% above the average (it keeps
// the components of a disconnected graph whole: two solids that do not touch),
// recursive bisection is tried and the better balanced result kept.
//
// Every tetrahedron gets one partition 1..n. A triangle, feature edge or
// corner vertex goes to the smallest partition among the tetrahedra that
// contain it (a feature edge that is no tetrahedron's edge, where features
// come closer than the minimum size: among those around its vertices). The writers then emit them:
// Gmsh 4.1 partitioned entities (one per model entity and partition, and the partition-boundary
// surfaces, curves and points, as Gmsh writes them: io/src/partition_boundaries.h), a `partition`
// cell array in .vtu; Medit has no place for them.
#pragma once

#include <cstddef>
#include <vector>

#include "rdmesh/tet_mesh.h"

namespace rdmesh {

struct PartitionStats {
  int parts = 0;
  /// Faces shared by two tetrahedra of different partitions (METIS's edge cut).
  std::size_t edge_cut = 0;
  /// Faces shared by two tetrahedra: the dual graph's edges.
  std::size_t dual_edges = 0;
  /// Largest partition's tetrahedra / average (1 = perfect balance).
  double imbalance = 1;
  std::vector<std::size_t> tets_per_part;
  double seconds = 0;
};

/// Splits `mesh` into `parts` partitions: fills TetMesh::tet_partition,
/// triangle_partition, edge_partition and corner_partition. Deterministic
/// (METIS with a fixed seed). Throws InputError when `parts` < 1, exceeds
/// the number of tetrahedra, or the mesh has no tetrahedra (a surface-only
/// mesh); InternalError when METIS fails.
PartitionStats partition_mesh(TetMesh& mesh, int parts);

}  // namespace rdmesh
