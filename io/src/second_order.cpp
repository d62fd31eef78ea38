// make_second_order: one mid node per edge, placed on the curve or patch the
// edge belongs to, then straightened where a tetrahedron's Jacobian would not
// stay positive (see second_order.h).
#include "rdmesh/second_order.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rdmesh/errors.h"
#include "rdmesh/stopwatch.h"

namespace rdmesh {
namespace {

using VertexPair = std::array<int, 2>;

VertexPair sorted_pair(int a, int b) { return a < b ? VertexPair{a, b} : VertexPair{b, a}; }

/// The sorted, unique vertex pairs of every element of the mesh.
std::vector<VertexPair> mesh_edges(const TetMesh& mesh) {
  std::vector<VertexPair> e;
  e.reserve(6 * mesh.tets.size() + 3 * mesh.triangles.size() + mesh.edges.size());
  for (const auto& t : mesh.tets) {
    for (const auto& [i, j] : kTetEdges) e.push_back(sorted_pair(t[i], t[j]));
  }
  for (const auto& f : mesh.triangles) {
    for (const auto& [i, j] : kTriangleEdges) e.push_back(sorted_pair(f[i], f[j]));
  }
  for (const auto& s : mesh.edges) e.push_back(sorted_pair(s[0], s[1]));
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

int edge_index(const std::vector<VertexPair>& edges, int a, int b) {
  const VertexPair key = sorted_pair(a, b);
  return static_cast<int>(std::lower_bound(edges.begin(), edges.end(), key) - edges.begin());
}

/// Where an edge's mid node goes: on a curve, on a patch, or on the chord.
struct Carrier {
  int curve = 0;  ///< curve id, 0 = none
  int patch = 0;  ///< patch id, 0 = none, -1 = triangles of several patches (no curve): chord
};

std::vector<Carrier> carriers(const TetMesh& mesh, const std::vector<VertexPair>& edges) {
  std::vector<Carrier> c(edges.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& tri = mesh.triangles[f];
    for (const auto& [i, j] : kTriangleEdges) {
      int& patch = c[edge_index(edges, tri[i], tri[j])].patch;
      const int p = mesh.triangle_patch[f].value;
      patch = patch == 0 || patch == p ? p : -1;
    }
  }
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    c[edge_index(edges, mesh.edges[e][0], mesh.edges[e][1])].curve = mesh.edge_curve[e].value;
  }
  return c;
}

/// The point of the curve nearest to the midpoint of [a, b], searched on the
/// arc between a's and b's closest points (the shorter way round a closed curve).
Point3 on_curve(const Curve& curve, const CurveInfo& info, const Point3& a, const Point3& b) {
  const Point3 mid = 0.5 * (a + b);
  const double ta = curve.closest(a, info.t_begin, info.t_end);
  const double tb = curve.closest(b, info.t_begin, info.t_end);
  const double lo = std::min(ta, tb), hi = std::max(ta, tb);
  if (info.closed && curve.length(lo, hi) > 0.5 * curve.length(info.t_begin, info.t_end)) {
    const Point3 p = curve.point(curve.closest(mid, info.t_begin, lo));
    const Point3 q = curve.point(curve.closest(mid, hi, info.t_end));
    return distance(p, mid) <= distance(q, mid) ? p : q;
  }
  return curve.point(curve.closest(mid, lo, hi));
}

/// Curved position of each mid node (the chord's midpoint where it stays straight).
struct Placement {
  std::vector<Point3> node;
  std::vector<char> curved;
};

Placement place_nodes(const TetMesh& mesh, const DomainOracle& oracle,
                      const std::vector<VertexPair>& edges, SecondOrderStats& stats) {
  const std::vector<Carrier> carrier = carriers(mesh, edges);
  std::map<int, CurveInfo> curve_info;
  for (const CurveInfo& c : oracle.curves()) curve_info[c.id.value] = c;
  Placement out{std::vector<Point3>(edges.size()), std::vector<char>(edges.size(), 0)};
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const Point3 &a = mesh.vertices[edges[e][0]], &b = mesh.vertices[edges[e][1]];
    const Point3 mid = 0.5 * (a + b);
    out.node[e] = mid;
    std::optional<Point3> p;
    const Carrier& c = carrier[e];
    if (c.curve > 0) {
      auto info = curve_info.find(c.curve);
      if (info == curve_info.end()) {
        throw InternalError("make_second_order: the mesh's curve " + std::to_string(c.curve) +
                            " is not one of the oracle's");
      }
      p = on_curve(oracle.curve(CurveId(c.curve)), info->second, a, b);
    } else if (c.patch > 0) {
      p = oracle.project(mid, PatchId(c.patch));
    } else {
      continue;
    }
    const double length = distance(a, b);
    if (!p || !is_finite(*p) || distance(*p, mid) > 0.5 * length) {
      ++stats.placement_failures;
      continue;
    }
    out.node[e] = *p;
    out.curved[e] = *p == mid ? 0 : 1;
    ++(c.curve > 0 ? stats.curve_nodes : stats.surface_nodes);
  }
  return out;
}

/// Straightens the curved nodes of every tetrahedron whose scaled Jacobian
/// bound is not above `threshold`, checking the neighbours of straightened
/// nodes again, until all pass; returns the smallest scaled bound.
double untangle(TetMesh& mesh, std::size_t first_mid, const std::vector<Point3>& chord,
                std::vector<char>& curved, double threshold, std::size_t& straightened) {
  const std::size_t nt = mesh.tets.size();
  // Tets around each mid node (CSR).
  std::vector<std::size_t> start(curved.size() + 1, 0);
  for (const auto& m : mesh.tet_mid_nodes) {
    for (int v : m) ++start[v - first_mid + 1];
  }
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<int> around(start.back());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < nt; ++t) {
    for (int v : mesh.tet_mid_nodes[t]) around[fill[v - first_mid]++] = static_cast<int>(t);
  }

  auto has_curved = [&](std::size_t t) {
    for (int v : mesh.tet_mid_nodes[t]) {
      if (curved[v - first_mid]) return true;
    }
    return false;
  };
  std::vector<int> queue;
  std::vector<char> queued(nt, 0);
  for (std::size_t t = 0; t < nt; ++t) {
    if (has_curved(t)) {
      queue.push_back(static_cast<int>(t));
      queued[t] = 1;
    }
  }
  // Straightens the node of edge e and queues the tets around it.
  auto straighten = [&](std::size_t e) {
    curved[e] = 0;
    mesh.vertices[first_mid + e] = chord[e];
    ++straightened;
    for (std::size_t i = start[e]; i < start[e + 1]; ++i) {
      if (!queued[around[i]]) {
        queued[around[i]] = 1;
        queue.push_back(around[i]);
      }
    }
  };
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const int t = queue[k];
    queued[t] = 0;
    // One node at a time, the one whose straightening helps most, until t passes.
    while (has_curved(t) && tet10_jacobian(tet10_nodes(mesh, t)).scaled() <= threshold) {
      int best = -1;
      double best_scaled = -std::numeric_limits<double>::infinity();
      for (int v : mesh.tet_mid_nodes[t]) {
        const std::size_t e = v - first_mid;
        if (!curved[e]) continue;
        const Point3 keep = mesh.vertices[v];
        mesh.vertices[v] = chord[e];
        const double scaled = tet10_jacobian(tet10_nodes(mesh, t)).scaled();
        mesh.vertices[v] = keep;
        if (scaled > best_scaled) {
          best_scaled = scaled;
          best = static_cast<int>(e);
        }
      }
      straighten(static_cast<std::size_t>(best));
    }
  }
  double min_scaled = 1;
  for (std::size_t t = 0; t < nt; ++t) {
    if (has_curved(t)) {
      min_scaled = std::min(min_scaled, tet10_jacobian(tet10_nodes(mesh, t)).scaled());
    }
  }
  return min_scaled;
}

}  // namespace

bool is_second_order(const TetMesh& mesh) {
  return !mesh.tet_mid_nodes.empty() || !mesh.triangle_mid_nodes.empty() ||
         !mesh.edge_mid_nodes.empty();
}

std::array<Point3, 10> tet10_nodes(const TetMesh& mesh, std::size_t t) {
  std::array<Point3, 10> x;
  for (int i = 0; i < 4; ++i) x[i] = mesh.vertices[mesh.tets[t][i]];
  for (int k = 0; k < 6; ++k) x[4 + k] = mesh.vertices[mesh.tet_mid_nodes[t][k]];
  return x;
}

SecondOrderStats make_second_order(TetMesh& mesh, const DomainOracle& oracle,
                                   const SecondOrderOptions& options) {
  const Stopwatch clock;
  if (is_second_order(mesh))
    throw InputError("make_second_order: the mesh is already second order");
  if (!(options.min_scaled_jacobian >= 0 && options.min_scaled_jacobian < 1)) {
    throw InputError("make_second_order: min_scaled_jacobian must be in [0, 1)");
  }
  SecondOrderStats stats;
  const std::vector<VertexPair> edges = mesh_edges(mesh);
  stats.mid_nodes = edges.size();
  Placement placed = place_nodes(mesh, oracle, edges, stats);

  const std::size_t first_mid = mesh.vertices.size();
  std::vector<Point3> chord(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const Point3 &a = mesh.vertices[edges[e][0]], &b = mesh.vertices[edges[e][1]];
    chord[e] = 0.5 * (a + b);
  }
  mesh.vertices.insert(mesh.vertices.end(), placed.node.begin(), placed.node.end());
  auto node = [&](int a, int b) { return static_cast<int>(first_mid) + edge_index(edges, a, b); };
  mesh.tet_mid_nodes.resize(mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (int k = 0; k < 6; ++k) {
      mesh.tet_mid_nodes[t][k] = node(mesh.tets[t][kTetEdges[k][0]], mesh.tets[t][kTetEdges[k][1]]);
    }
  }
  mesh.triangle_mid_nodes.resize(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      mesh.triangle_mid_nodes[f][k] =
          node(mesh.triangles[f][kTriangleEdges[k][0]], mesh.triangles[f][kTriangleEdges[k][1]]);
    }
  }
  mesh.edge_mid_nodes.resize(mesh.edges.size());
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    mesh.edge_mid_nodes[e] = node(mesh.edges[e][0], mesh.edges[e][1]);
  }

  stats.min_scaled_jacobian = untangle(mesh, first_mid, chord, placed.curved,
                                       options.min_scaled_jacobian, stats.straightened);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!placed.curved[e]) continue;
    const double length = distance(mesh.vertices[edges[e][0]], mesh.vertices[edges[e][1]]);
    stats.max_relative_offset = std::max(stats.max_relative_offset,
                                         distance(mesh.vertices[first_mid + e], chord[e]) / length);
  }
  stats.seconds = clock.seconds();
  return stats;
}

double mesh_volume(const TetMesh& mesh, SubdomainId id) {
  const bool p2 = mesh.tet_mid_nodes.size() == mesh.tets.size() && !mesh.tets.empty();
  double v = 0;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    if (id.value != 0 && mesh.tet_subdomain[t] != id) continue;
    if (p2) {
      v += tet10_jacobian(tet10_nodes(mesh, t)).volume;
    } else {
      const auto& q = mesh.tets[t];
      const Point3& a = mesh.vertices[q[0]];
      v += dot(mesh.vertices[q[1]] - a, cross(mesh.vertices[q[2]] - a, mesh.vertices[q[3]] - a)) /
           6.0;
    }
  }
  return v;
}

}  // namespace rdmesh
