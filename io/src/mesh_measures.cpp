// Geometric measures of a tetrahedron and topological checks of triangle sets.
#include "rdmesh/mesh_measures.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <numbers>

namespace rdmesh {
namespace {

/// Undirected edge key: (min << 32) | max, with indices reinterpreted as unsigned.
std::uint64_t edge_key(int a, int b) {
  auto lo = static_cast<std::uint32_t>(std::min(a, b));
  auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

/// The 3 edges of every triangle, sorted (duplicates kept).
std::vector<std::uint64_t> sorted_edges(const std::vector<std::array<int, 3>>& triangles) {
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * triangles.size());
  for (const auto& t : triangles) {
    edges.push_back(edge_key(t[0], t[1]));
    edges.push_back(edge_key(t[1], t[2]));
    edges.push_back(edge_key(t[2], t[0]));
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

/// The angle between the half-planes bounded by line (p, q) that contain r
/// and s, as the pair (sine, cosine) scaled by the same positive factor.
struct ScaledAngle {
  double sine, cosine;
  double degrees() const { return std::atan2(sine, cosine) * 180.0 / std::numbers::pi; }
  /// At a degenerate face both are 0, and degrees() is 0.
  bool degenerate() const { return sine == 0 && cosine == 0; }
  /// This angle is smaller than `o`. Both lie in [0, 180] degrees (their
  /// sines are >= 0): the smaller one turns counterclockwise to the other,
  /// unless they are 0 and 180 degrees (both sines 0).
  bool operator<(const ScaledAngle& o) const {
    if (degenerate() || o.degenerate()) return degenerate() && !o.degenerate();
    const double turn = cosine * o.sine - o.cosine * sine;
    if (turn != 0) return turn > 0;
    return cosine > 0 && o.cosine < 0;
  }
};

ScaledAngle angle_at_edge(const Point3& p, const Point3& q, const Point3& r, const Point3& s) {
  const Point3 e = q - p;
  const Point3 n1 = cross(e, r - p);  // normal of face (p, q, r), rotated copy of r's offset
  const Point3 n2 = cross(e, s - p);
  return {norm(cross(n1, n2)), dot(n1, n2)};
}

/// Angle in degrees between the half-planes bounded by line (p, q) that contain r and s.
double dihedral_at_edge(const Point3& p, const Point3& q, const Point3& r, const Point3& s) {
  return angle_at_edge(p, q, r, s).degrees();
}

/// The distinct vertices of `edges`, sorted.
std::vector<int> edge_vertices(const std::vector<std::array<int, 2>>& edges) {
  std::vector<int> vertices;
  vertices.reserve(2 * edges.size());
  for (const auto& e : edges) vertices.insert(vertices.end(), e.begin(), e.end());
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

/// Position of `v` in the sorted `vertices` (which contain it).
std::size_t rank_of(const std::vector<int>& vertices, int v) {
  return static_cast<std::size_t>(std::lower_bound(vertices.begin(), vertices.end(), v) -
                                  vertices.begin());
}

/// Union-find root of `i` with path halving.
std::size_t find_root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

int count_chain_components(const std::vector<std::array<int, 2>>& edges) {
  const std::vector<int> vertices = edge_vertices(edges);
  std::vector<std::size_t> parent(vertices.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  int components = static_cast<int>(vertices.size());
  for (const auto& e : edges) {
    const std::size_t a = find_root(parent, rank_of(vertices, e[0]));
    const std::size_t b = find_root(parent, rank_of(vertices, e[1]));
    if (a != b) {
      parent[a] = b;
      --components;
    }
  }
  return components;
}

bool is_simple_chain(const std::vector<std::array<int, 2>>& edges, bool closed) {
  if (edges.empty()) return false;
  std::vector<std::uint64_t> keys;
  keys.reserve(edges.size());
  for (const auto& e : edges) {
    if (e[0] == e[1]) return false;
    keys.push_back(edge_key(e[0], e[1]));
  }
  std::sort(keys.begin(), keys.end());
  if (std::adjacent_find(keys.begin(), keys.end()) != keys.end()) return false;

  const std::vector<int> vertices = edge_vertices(edges);
  std::vector<int> degree(vertices.size(), 0);
  for (const auto& e : edges) {
    ++degree[rank_of(vertices, e[0])];
    ++degree[rank_of(vertices, e[1])];
  }
  const auto ends = std::count(degree.begin(), degree.end(), 1);
  const auto middles = std::count(degree.begin(), degree.end(), 2);
  if (ends + middles != static_cast<long>(degree.size()) || ends != (closed ? 0 : 2)) return false;
  return count_chain_components(edges) == 1;
}

int euler_characteristic(const std::vector<std::array<int, 3>>& triangles) {
  std::vector<int> vertices;
  vertices.reserve(3 * triangles.size());
  for (const auto& t : triangles) vertices.insert(vertices.end(), t.begin(), t.end());
  std::sort(vertices.begin(), vertices.end());
  const auto num_vertices = std::unique(vertices.begin(), vertices.end()) - vertices.begin();
  std::vector<std::uint64_t> edges = sorted_edges(triangles);
  const auto num_edges = std::unique(edges.begin(), edges.end()) - edges.begin();
  return static_cast<int>(num_vertices - num_edges + static_cast<long>(triangles.size()));
}

bool is_edge_manifold(const std::vector<std::array<int, 3>>& triangles) {
  const std::vector<std::uint64_t> edges = sorted_edges(triangles);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i != 2) return false;
    i = j;
  }
  return true;
}

double signed_volume(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  return dot(b - a, cross(c - a, d - a)) / 6.0;
}

std::vector<double> dihedral_angles_deg(const Point3& a, const Point3& b, const Point3& c,
                                        const Point3& d) {
  return {dihedral_at_edge(a, b, c, d), dihedral_at_edge(a, c, b, d), dihedral_at_edge(a, d, b, c),
          dihedral_at_edge(b, c, a, d), dihedral_at_edge(b, d, a, c), dihedral_at_edge(c, d, a, b)};
}

std::pair<double, double> dihedral_extremes_deg(const Point3& a, const Point3& b, const Point3& c,
                                                const Point3& d) {
  const ScaledAngle angles[6] = {angle_at_edge(a, b, c, d), angle_at_edge(a, c, b, d),
                                 angle_at_edge(a, d, b, c), angle_at_edge(b, c, a, d),
                                 angle_at_edge(b, d, a, c), angle_at_edge(c, d, a, b)};
  const auto [lo, hi] = std::minmax_element(std::begin(angles), std::end(angles));
  return {lo->degrees(), hi->degrees()};
}

double radius_edge_ratio(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const Point3 u = b - a, v = c - a, w = d - a;
  const double det = 2.0 * dot(u, cross(v, w));
  const double shortest =
      std::sqrt(std::min({squared_norm(u), squared_norm(v), squared_norm(w), squared_norm(c - b),
                          squared_norm(d - b), squared_norm(d - c)}));
  if (det == 0.0 || shortest == 0.0) return std::numeric_limits<double>::infinity();
  // Circumcentre offset from a: (|u|^2 v x w + |v|^2 w x u + |w|^2 u x v) / det.
  const Point3 offset =
      squared_norm(u) * cross(v, w) + squared_norm(v) * cross(w, u) + squared_norm(w) * cross(u, v);
  return norm(offset) / std::abs(det) / shortest;
}

}  // namespace rdmesh
