// Test helper: reads the partitioned entities and the elements of an ASCII
// .msh 4.1 file, and checks the partition-boundary entities of a written
// partitioned mesh against the faces, edges and vertices of the TetMesh:
// - every face shared by tetrahedra of two partitions is written once, as a
//   model triangle when it lies on a patch, else as a triangle of a
//   partition-boundary surface whose partitions are exactly those two and
//   whose parent is the tetrahedra's subdomain;
// - the boundary curves' edges are exactly the edges, not feature edges, of
//   triangles of two or more surface entities spanning two or more partitions,
//   with a patch as parent when a patch triangle has the edge, else a subdomain;
// - the boundary points are exactly the vertices, not corners, of lines of two
//   or more curve entities spanning two or more partitions.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "rdmesh/tet_mesh.h"

namespace rdmesh::testing {

struct MshEntity {
  int dim = 0, tag = 0, parent_dim = 0, parent = 0;
  std::vector<int> partitions;
  std::vector<std::vector<int>> elements;  ///< 0-based node indices
};

struct MshPartitions {
  int num_partitions = 0;
  std::map<std::pair<int, int>, MshEntity> entities;  ///< by (dim, tag)
};

/// Reads $PartitionedEntities and $Elements of an ASCII partitioned .msh 4.1 text.
inline MshPartitions read_msh_partitions(const std::string& text) {
  MshPartitions out;
  std::istringstream in(text.substr(text.find("$PartitionedEntities")));
  std::string word;
  in >> word >> out.num_partitions;
  int ghosts = 0;
  in >> ghosts;
  std::array<int, 4> count{};
  for (int& c : count) in >> c;
  for (int dim = 0; dim < 4; ++dim) {
    for (int k = 0; k < count[dim]; ++k) {
      MshEntity e;
      e.dim = dim;
      int n = 0;
      in >> e.tag >> e.parent_dim >> e.parent >> n;
      e.partitions.resize(n);
      for (int& p : e.partitions) in >> p;
      double x = 0;
      for (int c = 0; c < (dim == 0 ? 3 : 6); ++c) in >> x;
      int skip = 0;
      for (int pass = 0; pass < (dim == 0 ? 1 : 2); ++pass) {
        in >> n;
        for (int i = 0; i < n; ++i) in >> skip;
      }
      out.entities[{dim, e.tag}] = e;
    }
  }
  in.clear();
  in.str(text.substr(text.find("$Elements")));
  long long blocks = 0, total = 0, lo = 0, hi = 0;
  in >> word >> blocks >> total >> lo >> hi;
  const std::map<int, int> nodes_of_type{{1, 2}, {2, 3}, {4, 4}, {8, 3}, {9, 6}, {11, 10}, {15, 1}};
  for (long long b = 0; b < blocks; ++b) {
    int dim = 0, tag = 0, type = 0;
    long long n = 0, id = 0;
    in >> dim >> tag >> type >> n;
    MshEntity& e = out.entities[{dim, tag}];
    for (long long i = 0; i < n; ++i) {
      in >> id;
      std::vector<int> nodes(nodes_of_type.at(type));
      for (int& v : nodes) {
        in >> v;
        --v;
      }
      e.elements.push_back(nodes);
    }
  }
  return out;
}

template <std::size_t N>
std::array<int, N> sorted_cell(const std::vector<int>& nodes) {
  std::array<int, N> a{};
  std::copy_n(nodes.begin(), N, a.begin());
  std::sort(a.begin(), a.end());
  return a;
}

/// The union of two ascending lists.
inline std::vector<int> union_of(const std::vector<int>& a, const std::vector<int>& b) {
  std::set<int> s(a.begin(), a.end());
  s.insert(b.begin(), b.end());
  return {s.begin(), s.end()};
}

/// Checks the partition-boundary entities of `msh` (the ASCII file written
/// for the partitioned `mesh`); returns the number of boundary entities per dimension.
inline std::array<std::size_t, 3> expect_partition_boundaries(const TetMesh& mesh,
                                                              const std::string& msh) {
  const MshPartitions file = read_msh_partitions(msh);
  const int parts = *std::max_element(mesh.tet_partition.begin(), mesh.tet_partition.end());
  EXPECT_EQ(file.num_partitions, parts);
  std::array<std::size_t, 3> boundary_entities{};
  // Faces of the mesh between two partitions, with their subdomain.
  std::map<std::array<int, 3>, std::vector<int>> tets_of_face;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (int skip = 0; skip < 4; ++skip) {
      std::vector<int> f;
      for (int i = 0; i < 4; ++i) {
        if (i != skip) f.push_back(mesh.tets[t][i]);
      }
      tets_of_face[sorted_cell<3>(f)].push_back(static_cast<int>(t));
    }
  }
  std::set<std::array<int, 3>> model_faces;
  for (const auto& f : mesh.triangles) model_faces.insert(sorted_cell<3>({f[0], f[1], f[2]}));
  std::set<std::array<int, 2>> feature_edges;
  for (const auto& e : mesh.edges) feature_edges.insert(sorted_cell<2>({e[0], e[1]}));
  std::set<int> corners(mesh.corner_vertices.begin(), mesh.corner_vertices.end());

  std::map<std::array<int, 3>, int> written_faces;  // how many triangle elements
  std::map<std::array<int, 2>, std::set<int>> surfaces_at_edge;
  std::map<std::array<int, 2>, int> boundary_edges;
  std::map<int, std::set<int>> curves_at_vertex;
  std::map<int, int> boundary_points;
  for (const auto& [key, e] : file.entities) {
    const bool boundary = e.partitions.size() >= 2;
    if (boundary) ++boundary_entities[e.dim];
    if (e.dim == 2) {
      for (const auto& nodes : e.elements) {
        const auto f = sorted_cell<3>(nodes);
        ++written_faces[f];
        for (int i = 0; i < 3; ++i) {
          surfaces_at_edge[sorted_cell<2>({f[i], f[(i + 1) % 3]})].insert(e.tag);
        }
        if (!boundary) continue;
        EXPECT_EQ(model_faces.count(f), 0u) << "a patch triangle on a boundary surface";
        const auto& tets = tets_of_face.at(f);
        EXPECT_EQ(tets.size(), 2u);
        if (tets.size() != 2) continue;
        const int p = mesh.tet_partition[tets[0]], q = mesh.tet_partition[tets[1]];
        EXPECT_EQ(e.partitions, (std::vector<int>{std::min(p, q), std::max(p, q)}));
        EXPECT_EQ(e.parent_dim, 3);
        EXPECT_EQ(e.parent, mesh.tet_subdomain[tets[0]].value);
      }
    } else if (e.dim == 1) {
      for (const auto& nodes : e.elements) {
        for (int v : {nodes[0], nodes[1]}) curves_at_vertex[v].insert(e.tag);
        if (boundary) ++boundary_edges[sorted_cell<2>(nodes)];
        if (boundary) {  // on a patch exactly when a patch triangle has the edge
          const auto edge = sorted_cell<2>(nodes);
          bool on_patch = false;
          for (const auto& f : mesh.triangles) {
            on_patch |=
                std::count(f.begin(), f.end(), edge[0]) && std::count(f.begin(), f.end(), edge[1]);
          }
          EXPECT_EQ(e.parent_dim, on_patch ? 2 : 3);
        }
      }
    } else if (e.dim == 0 && boundary) {
      for (const auto& nodes : e.elements) ++boundary_points[nodes[0]];
    }
  }
  // Every face between partitions once; no other faces beyond the patches'.
  for (const auto& [f, tets] : tets_of_face) {
    const bool cut = tets.size() == 2 && mesh.tet_partition[tets[0]] != mesh.tet_partition[tets[1]];
    if (!cut && !model_faces.count(f)) {
      EXPECT_EQ(written_faces.count(f), 0u);
    } else {
      EXPECT_EQ(written_faces[f], 1) << "a face between partitions or on a patch";
    }
  }
  // Boundary curves: edges where surfaces of two partitions or more meet.
  auto partitions_of = [&](const std::set<int>& tags, int dim) {
    std::vector<int> all;
    for (int tag : tags) all = union_of(all, file.entities.at({dim, tag}).partitions);
    return all;
  };
  std::size_t expected_edges = 0;
  for (const auto& [edge, tags] : surfaces_at_edge) {
    if (tags.size() < 2 || feature_edges.count(edge) || partitions_of(tags, 2).size() < 2) {
      EXPECT_EQ(boundary_edges.count(edge), 0u);
      continue;
    }
    ++expected_edges;
    EXPECT_EQ(boundary_edges[edge], 1) << "edge " << edge[0] << "-" << edge[1];
  }
  EXPECT_EQ(boundary_edges.size(), expected_edges);
  std::size_t expected_points = 0;
  for (const auto& [v, tags] : curves_at_vertex) {
    if (tags.size() < 2 || corners.count(v) || partitions_of(tags, 1).size() < 2) {
      EXPECT_EQ(boundary_points.count(v), 0u);
      continue;
    }
    ++expected_points;
    EXPECT_EQ(boundary_points[v], 1) << "vertex " << v;
  }
  EXPECT_EQ(boundary_points.size(), expected_points);
  return boundary_entities;
}

}  // namespace rdmesh::testing
