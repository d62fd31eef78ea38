// partition_boundaries: faces between partitions, then the edges and vertices
// where entities of different (parent, partitions) meet (see the header).
#include "partition_boundaries.h"

#include <algorithm>
#include <climits>
#include <map>
#include <tuple>
#include <utility>

#include "rdmesh/errors.h"
#include "tet_faces.h"

namespace rdmesh::io_detail {
namespace {

/// (parent dimension, parent, partitions): what makes elements one entity.
using Key = std::tuple<int, int, std::vector<int>>;

/// A tetrahedron's faces, outward for a positively oriented one, by skipped vertex.
constexpr std::array<std::array<int, 3>, 4> kOutwardFaces{
    {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};

std::vector<int> merged(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> out;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

template <std::size_t N>
std::array<int, N> sorted(std::array<int, N> a) {
  std::sort(a.begin(), a.end());
  return a;
}

/// Elements grouped by key, in key order.
using Groups = std::map<Key, std::vector<std::vector<int>>>;

/// The mid-edge nodes of a second-order mesh on the edges of the given
/// elements (from the tetrahedra and the patch triangles that have them).
class MidNodes {
 public:
  MidNodes(const TetMesh& mesh, const std::vector<const Groups*>& groups) {
    if (mesh.tet_mid_nodes.size() != mesh.tets.size() || mesh.tets.empty()) return;
    for (const Groups* g : groups) {
      for (const auto& [key, elements] : *g) {
        for (const auto& e : elements)
          for_each_edge(e, [&](int a, int b) { edges_.push_back(sorted_pair(a, b)); });
      }
    }
    std::sort(edges_.begin(), edges_.end());
    edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
    mid_.assign(edges_.size(), -1);
    auto found = [&](int a, int b, int node) {
      const long i = index(a, b);
      if (i >= 0) mid_[i] = node;
    };
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      for (std::size_t k = 0; k < kTetEdges.size(); ++k) {
        found(mesh.tets[t][kTetEdges[k][0]], mesh.tets[t][kTetEdges[k][1]],
              mesh.tet_mid_nodes[t][k]);
      }
    }
    for (std::size_t f = 0; f < mesh.triangle_mid_nodes.size(); ++f) {
      for (std::size_t k = 0; k < kTriangleEdges.size(); ++k) {
        found(mesh.triangles[f][kTriangleEdges[k][0]], mesh.triangles[f][kTriangleEdges[k][1]],
              mesh.triangle_mid_nodes[f][k]);
      }
    }
  }
  /// Appends the mid nodes of the edges 01, 12, 20 (or 01 for a line, none
  /// for a point) of `nodes`.
  void complete(std::vector<int>& nodes) const {
    if (mid_.empty()) return;
    const std::vector<int> ends = nodes;
    for_each_edge(ends, [&](int a, int b) {
      const long i = index(a, b);
      const int node = i >= 0 ? mid_[i] : -1;
      if (node < 0) {
        throw InternalError("write_gmsh41: a partition-boundary edge has no mid-edge node");
      }
      nodes.push_back(node);
    });
  }

 private:
  /// The edges 01, 12, 20 of a triangle, 01 of a line, none of a point.
  template <class F>
  static void for_each_edge(const std::vector<int>& e, F f) {
    const std::size_t n = e.size();
    if (n < 2) return;
    for (std::size_t i = 0; i < (n == 2 ? 1 : n); ++i) f(e[i], e[(i + 1) % n]);
  }
  static std::pair<int, int> sorted_pair(int a, int b) { return {std::min(a, b), std::max(a, b)}; }
  /// The position of edge (a, b) in edges_, -1 if absent.
  long index(int a, int b) const {
    const auto key = sorted_pair(a, b);
    auto it = std::lower_bound(edges_.begin(), edges_.end(), key);
    return it != edges_.end() && *it == key ? it - edges_.begin() : -1;
  }
  std::vector<std::pair<int, int>> edges_;
  std::vector<int> mid_;
};

/// The connected pieces of `elements` (sharing `shared` nodes: 2 for faces
/// sharing an edge, 1 for lines sharing a vertex that is not `cut`), each in
/// element order, the pieces by their first element.
std::vector<std::vector<std::vector<int>>> connected_pieces(std::vector<std::vector<int>> elements,
                                                            int shared,
                                                            const std::vector<char>& cut) {
  std::vector<int> root(elements.size());
  for (std::size_t i = 0; i < root.size(); ++i) root[i] = static_cast<int>(i);
  auto find = [&](int i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  std::map<std::vector<int>, int> first_with;  // a shared sub-cell -> an element
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const auto& e = elements[i];
    const std::size_t n = e.size();
    for (std::size_t k = 0; shared > 0 && k < n; ++k) {
      if (shared == 1 && cut[e[k]]) continue;
      std::vector<int> sub{e[k]};
      if (shared == 2) sub = {std::min(e[k], e[(k + 1) % n]), std::max(e[k], e[(k + 1) % n])};
      auto [it, added] = first_with.emplace(sub, static_cast<int>(i));
      if (!added) {
        const int a = find(it->second), b = find(static_cast<int>(i));
        root[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  std::map<int, std::vector<std::vector<int>>> pieces;  // by the smallest element
  for (std::size_t i = 0; i < elements.size(); ++i) {
    pieces[find(static_cast<int>(i))].push_back(std::move(elements[i]));
  }
  std::vector<std::vector<std::vector<int>>> out;
  for (auto& [first, piece] : pieces) out.push_back(std::move(piece));
  return out;
}

/// One entity per connected piece of each group (as Gmsh splits them), whose
/// elements share `shared` nodes (lines: not through `cut` vertices); each
/// point is its own entity.
std::vector<PartitionBoundary> to_entities(Groups groups, const MidNodes& mid, int shared,
                                           const std::vector<char>& cut = {}) {
  std::vector<PartitionBoundary> out;
  for (auto& [key, elements] : groups) {
    for (auto& piece : connected_pieces(std::move(elements), shared, cut)) {
      for (auto& e : piece) mid.complete(e);
      out.push_back({std::get<0>(key), std::get<1>(key), std::get<2>(key), std::move(piece)});
    }
  }
  return out;
}

/// Elements of dimension d-1 incident to entities of dimension d: (cell, key index).
template <std::size_t N>
struct Incidence {
  std::array<int, N> cell;
  int key;
  bool operator<(const Incidence& o) const { return std::tie(cell, key) < std::tie(o.cell, o.key); }
};

/// For each cell shared by elements of at least two different keys whose
/// partitions are not all one: `emit` (cell, union of their partitions).
/// `records` must be sorted.
template <std::size_t N, class Emit>
void for_each_meeting(const std::vector<Incidence<N>>& records, const std::vector<Key>& keys,
                      Emit emit) {
  for (std::size_t i = 0; i < records.size();) {
    std::size_t j = i;
    std::vector<int> partitions;
    int distinct = 0;
    for (; j < records.size() && records[j].cell == records[i].cell; ++j) {
      if (j == i || records[j].key != records[j - 1].key) ++distinct;
      partitions = merged(partitions, std::get<2>(keys[records[j].key]));
    }
    if (distinct >= 2 && partitions.size() >= 2) emit(records[i].cell, std::move(partitions));
    i = j;
  }
}

/// The smallest id per vertex over the given elements (INT_MAX where none).
template <std::size_t N, class Id>
std::vector<int> smallest_id(std::size_t num_vertices, const std::vector<std::array<int, N>>& cells,
                             const std::vector<Id>& ids) {
  std::vector<int> out(num_vertices, INT_MAX);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    for (int v : cells[c]) out[v] = std::min(out[v], ids[c].value);
  }
  return out;
}

}  // namespace

PartitionBoundaries partition_boundaries(const TetMesh& mesh) {
  const std::size_t nv = mesh.vertices.size();
  // Faces between partitions, not on a patch.
  std::vector<std::array<int, 3>> model_faces;
  for (const auto& f : mesh.triangles) model_faces.push_back(sorted(f));
  std::sort(model_faces.begin(), model_faces.end());
  Groups surfaces;
  for_each_shared_face(mesh, [&](const TetFace& a, const TetFace& b) {
    const int pa = mesh.tet_partition[a.tet], pb = mesh.tet_partition[b.tet];
    if (pa == pb || std::binary_search(model_faces.begin(), model_faces.end(), a.v)) return;
    const TetFace& low = pa < pb ? a : b;  // oriented out of the smaller partition
    const auto& tv = mesh.tets[low.tet];
    const auto& l = kOutwardFaces[low.skip];
    surfaces[{3, mesh.tet_subdomain[low.tet].value, {std::min(pa, pb), std::max(pa, pb)}}]
        .push_back({tv[l[0]], tv[l[1]], tv[l[2]]});
  });

  // Edges where partitioned patches and boundary surfaces of different keys meet.
  std::vector<Key> keys;
  std::map<Key, int> key_index;
  auto index_of = [&](const Key& k) {
    auto [it, added] = key_index.emplace(k, static_cast<int>(keys.size()));
    if (added) keys.push_back(k);
    return it->second;
  };
  std::vector<Incidence<2>> edge_records;
  auto add_triangle_edges = [&](const std::vector<int>& v, int key) {
    for (int i = 0; i < 3; ++i) edge_records.push_back({sorted<2>({v[i], v[(i + 1) % 3]}), key});
  };
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& v = mesh.triangles[f];
    add_triangle_edges({v[0], v[1], v[2]},
                       index_of({2, mesh.triangle_patch[f].value, {mesh.triangle_partition[f]}}));
  }
  for (const auto& [key, elements] : surfaces) {
    const int k = index_of(key);
    for (const auto& e : elements) add_triangle_edges(e, k);
  }
  std::sort(edge_records.begin(), edge_records.end());
  std::vector<std::array<int, 2>> model_edges;
  for (const auto& e : mesh.edges) model_edges.push_back(sorted(e));
  std::sort(model_edges.begin(), model_edges.end());
  const std::vector<int> patch_at = smallest_id(nv, mesh.triangles, mesh.triangle_patch);
  const std::vector<int> subdomain_at = smallest_id(nv, mesh.tets, mesh.tet_subdomain);
  Groups curves;
  for_each_meeting(edge_records, keys, [&](const std::array<int, 2>& e, std::vector<int> parts) {
    if (std::binary_search(model_edges.begin(), model_edges.end(), e)) return;
    // On a patch when a model triangle has this edge (records of dimension 2).
    int patch = INT_MAX, subdomain = INT_MAX;
    auto range = std::equal_range(edge_records.begin(), edge_records.end(), Incidence<2>{e, -1},
                                  [](const auto& x, const auto& y) { return x.cell < y.cell; });
    for (auto it = range.first; it != range.second; ++it) {
      const Key& k = keys[it->key];
      int& best = std::get<0>(k) == 2 ? patch : subdomain;
      best = std::min(best, std::get<1>(k));
    }
    const Key key =
        patch != INT_MAX ? Key{2, patch, std::move(parts)} : Key{3, subdomain, std::move(parts)};
    curves[key].push_back({e[0], e[1]});
  });

  // Vertices where partitioned curves and boundary curves of different keys meet.
  std::vector<Incidence<1>> vertex_records;
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const int k = index_of({1, mesh.edge_curve[e].value, {mesh.edge_partition[e]}});
    for (int v : mesh.edges[e]) vertex_records.push_back({{v}, k});
  }
  for (const auto& [key, elements] : curves) {
    const int k = index_of(key);
    for (const auto& e : elements) {
      for (int v : e) vertex_records.push_back({{v}, k});
    }
  }
  std::sort(vertex_records.begin(), vertex_records.end());
  std::vector<char> is_corner(nv, 0);
  for (int v : mesh.corner_vertices) is_corner[v] = 1;
  const std::vector<int> curve_at = smallest_id(nv, mesh.edges, mesh.edge_curve);
  Groups points;
  for_each_meeting(vertex_records, keys, [&](const std::array<int, 1>& c, std::vector<int> parts) {
    const int v = c[0];
    if (is_corner[v]) return;
    Key key = curve_at[v] != INT_MAX   ? Key{1, curve_at[v], std::move(parts)}
              : patch_at[v] != INT_MAX ? Key{2, patch_at[v], std::move(parts)}
                                       : Key{3, subdomain_at[v], std::move(parts)};
    points[std::move(key)].push_back({v});
  });
  const MidNodes mid(mesh, {&surfaces, &curves});
  // Curves end at points and corners, as Gmsh's do.
  std::vector<char> ends = is_corner;
  for (const auto& [key, elements] : points) {
    for (const auto& e : elements) ends[e.front()] = 1;
  }
  return {to_entities(std::move(points), mid, 0),
          to_entities(std::move(curves), mid, 1, ends),
          to_entities(std::move(surfaces), mid, 2),
          {}};
}

}  // namespace rdmesh::io_detail
