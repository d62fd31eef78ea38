// partition_mesh: the tetrahedra's dual graph, METIS k-way, then the
// partitions of the lower-dimensional elements (see partition.h).
#include "rdmesh/partition.h"

#include <metis.h>

#include <algorithm>
#include <array>
#include <string>

#include "rdmesh/errors.h"
#include "rdmesh/stopwatch.h"
#include "tet_faces.h"

namespace rdmesh {
namespace {

/// Tetrahedra around each vertex, ascending: CSR arrays.
struct VertexTets {
  std::vector<std::size_t> start;
  std::vector<int> tets;
  template <class F>
  void for_each(int v, F f) const {
    for (std::size_t i = start[v]; i < start[v + 1]; ++i) f(tets[i]);
  }
};

VertexTets vertex_tets(const TetMesh& mesh) {
  VertexTets vt;
  vt.start.assign(mesh.vertices.size() + 1, 0);
  auto nodes_of = [&](std::size_t t, auto f) {
    for (int v : mesh.tets[t]) f(v);
  };
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) nodes_of(t, [&](int v) { ++vt.start[v + 1]; });
  for (std::size_t i = 1; i < vt.start.size(); ++i) vt.start[i] += vt.start[i - 1];
  vt.tets.resize(vt.start.back());
  std::vector<std::size_t> fill(vt.start.begin(), vt.start.end() - 1);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    nodes_of(t, [&](int v) { vt.tets[fill[v]++] = static_cast<int>(t); });
  }
  return vt;
}

bool has_vertex(const std::array<int, 4>& tet, int v) {
  return std::find(tet.begin(), tet.end(), v) != tet.end();
}

/// The smallest partition among the tetrahedra around `first` that contain all
/// of `others`; for an element that is no tetrahedron's face or edge (a feature
/// edge the refinement could not recover where features come closer than the
/// minimum size), among the tetrahedra around any of its vertices.
template <class Others>
int smallest_partition(const TetMesh& mesh, const VertexTets& vt, int first, const Others& others) {
  int best = 0;
  auto consider = [&](int t) {
    const int p = mesh.tet_partition[t];
    if (best == 0 || p < best) best = p;
  };
  vt.for_each(first, [&](int t) {
    for (int v : others) {
      if (!has_vertex(mesh.tets[t], v)) return;
    }
    consider(t);
  });
  if (best == 0) {
    vt.for_each(first, consider);
    for (int v : others) vt.for_each(v, consider);
  }
  if (best == 0) {
    throw InternalError("partition_mesh: a vertex of the mesh lies on no tetrahedron");
  }
  return best;
}

/// The dual graph in METIS's CSR form: tetrahedra sharing a face.
struct DualGraph {
  std::vector<idx_t> xadj, adjncy;
};

DualGraph dual_graph(const TetMesh& mesh) {
  std::vector<std::array<int, 2>> edges;
  io_detail::for_each_shared_face(mesh,
                                  [&](const io_detail::TetFace& a, const io_detail::TetFace& b) {
                                    edges.push_back({a.tet, b.tet});
                                    edges.push_back({b.tet, a.tet});
                                  });
  std::sort(edges.begin(), edges.end());
  DualGraph g;
  g.xadj.assign(mesh.tets.size() + 1, 0);
  g.adjncy.reserve(edges.size());
  for (const auto& [a, b] : edges) {
    ++g.xadj[a + 1];
    g.adjncy.push_back(b);
  }
  for (std::size_t i = 1; i < g.xadj.size(); ++i) g.xadj[i] += g.xadj[i - 1];
  return g;
}

/// The balance asked of METIS (partition.h): largest part / average.
constexpr double kMaxImbalance = 1.03;

/// Largest partition / average partition of a METIS result.
double largest_share(const std::vector<idx_t>& part, int parts) {
  std::vector<std::size_t> count(parts, 0);
  for (idx_t p : part) ++count[p];
  return static_cast<double>(*std::max_element(count.begin(), count.end())) * parts /
         static_cast<double>(part.size());
}

}  // namespace

PartitionStats partition_mesh(TetMesh& mesh, int parts) {
  const Stopwatch clock;
  if (mesh.tets.empty()) {
    throw InputError("partitions need tetrahedra: a surface-only mesh cannot be partitioned");
  }
  if (parts < 1 || static_cast<std::size_t>(parts) > mesh.tets.size()) {
    throw InputError("cannot make " + std::to_string(parts) + " partitions of " +
                     std::to_string(mesh.tets.size()) + " tetrahedra");
  }
  PartitionStats stats;
  stats.parts = parts;
  DualGraph g = dual_graph(mesh);
  stats.dual_edges = g.adjncy.size() / 2;
  std::vector<idx_t> part(mesh.tets.size(), 0);
  if (parts > 1) {
    idx_t nvtxs = static_cast<idx_t>(mesh.tets.size()), ncon = 1, nparts = parts, objval = 0;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_SEED] = 1;
    options[METIS_OPTION_NUMBERING] = 0;
    options[METIS_OPTION_UFACTOR] = 10;  // aim at 1%: METIS may overshoot, 3% is the bound
    int status =
        METIS_PartGraphKway(&nvtxs, &ncon, g.xadj.data(), g.adjncy.data(), nullptr, nullptr,
                            nullptr, &nparts, nullptr, nullptr, options, &objval, part.data());
    // k-way may keep a disconnected graph's components whole (no cut) beyond
    // the balance asked; recursive bisection splits them.
    if (status == METIS_OK && largest_share(part, parts) > kMaxImbalance) {
      std::vector<idx_t> bisected(part.size(), 0);
      status = METIS_PartGraphRecursive(&nvtxs, &ncon, g.xadj.data(), g.adjncy.data(), nullptr,
                                        nullptr, nullptr, &nparts, nullptr, nullptr, options,
                                        &objval, bisected.data());
      if (status == METIS_OK && largest_share(bisected, parts) < largest_share(part, parts)) {
        part = bisected;
      }
    }
    if (status != METIS_OK) {
      throw InternalError("partition_mesh: METIS failed (status " + std::to_string(status) + ")");
    }
  }
  mesh.tet_partition.assign(part.begin(), part.end());
  for (int& p : mesh.tet_partition) ++p;

  stats.tets_per_part.assign(parts, 0);
  for (int p : mesh.tet_partition) ++stats.tets_per_part[p - 1];
  const double average = static_cast<double>(mesh.tets.size()) / parts;
  stats.imbalance =
      *std::max_element(stats.tets_per_part.begin(), stats.tets_per_part.end()) / average;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (idx_t i = g.xadj[t]; i < g.xadj[t + 1]; ++i) {
      const auto u = static_cast<std::size_t>(g.adjncy[i]);
      stats.edge_cut += t < u && mesh.tet_partition[t] != mesh.tet_partition[u];
    }
  }

  const VertexTets vt = vertex_tets(mesh);
  mesh.triangle_partition.resize(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& v = mesh.triangles[f];
    mesh.triangle_partition[f] = smallest_partition(mesh, vt, v[0], std::array<int, 2>{v[1], v[2]});
  }
  mesh.edge_partition.resize(mesh.edges.size());
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const auto& v = mesh.edges[e];
    mesh.edge_partition[e] = smallest_partition(mesh, vt, v[0], std::array<int, 1>{v[1]});
  }
  mesh.corner_partition.resize(mesh.corner_vertices.size());
  for (std::size_t c = 0; c < mesh.corner_vertices.size(); ++c) {
    mesh.corner_partition[c] =
        smallest_partition(mesh, vt, mesh.corner_vertices[c], std::array<int, 0>{});
  }
  stats.seconds = clock.seconds();
  return stats;
}

}  // namespace rdmesh
