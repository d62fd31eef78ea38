// ImplicitOracle::sample_box: discovers the patches, their connected components
// and initial points on a regular grid over the bounding box.
//
// 1. label_grid: label every grid node with locate().
// 2. grid_crossings: every grid edge whose end labels differ is a crossing:
//    intersect() on it gives a point and the patch actually crossed.
// 3. connected_components: two crossings of the same patch on edges of a
//    common grid cell belong to the same connected component (union-find), as
//    in marching cubes. number_patches then numbers the patches found.
// 4. component_points: each component contributes one crossing per kCrossingsPerPoint (at least
//    kPointsPerComponent, at most kMaxPointsPerComponent), chosen by
//    farthest-point sampling (spread out, deterministic). A handful of points is
//    not enough: the Delaunay triangulation of 8 points on a torus has no
//    Voronoi vertex inside the tube, so the refinement would see no restricted
//    facet at all; a sample spaced at a few grid cells captures the topology. A component with
//    fewer than three crossings (smaller than a grid cell) is enriched with crossings of
//    grid-parallel segments shifted by fractions of a cell.
// 5. check_surface_seen refuses a surface seen at fewer than 4 points;
//    name_patches names the patches by their sides.

#include <algorithm>
#include <limits>
#include <numeric>
#include <string>

#include "rdmesh/errors.h"
#include "rdmesh/implicit_oracle.h"

namespace rdmesh {

namespace {

constexpr int kPointsPerComponent = 8;
constexpr int kMaxPointsPerComponent = 200;
constexpr int kCrossingsPerPoint = 24;
constexpr int kMinPointsPerComponent = 3;

struct Crossing {
  int edge;  // 3 * lower node + axis
  Point3 point;
  int patch;
};

class UnionFind {
 public:
  explicit UnionFind(int n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void unite(int i, int j) {
    i = find(i), j = find(j);
    if (i != j) parent_[std::max(i, j)] = std::min(i, j);
  }

 private:
  std::vector<int> parent_;
};

/// Indices of up to `count` crossings of `members`, spread by farthest-point
/// sampling. (Squared distances: the square roots took half the oracle's set-up
/// for the unit sphere, 200 points over 7.5 k crossings.)
std::vector<int> spread(const std::vector<Crossing>& crossings, const std::vector<int>& members,
                        int count) {
  std::vector<int> chosen{members.front()};
  std::vector<double> dist(members.size(), std::numeric_limits<double>::infinity());
  while (static_cast<int>(chosen.size()) < std::min<int>(count, members.size())) {
    const Point3 last = crossings[chosen.back()].point;
    std::size_t far = 0;
    for (std::size_t m = 0; m < members.size(); ++m) {
      dist[m] = std::min(dist[m], squared_norm(crossings[members[m]].point - last));
      if (dist[m] > dist[far]) far = m;
    }
    if (!(dist[far] > 0)) break;
    chosen.push_back(members[far]);
  }
  return chosen;
}

}  // namespace

namespace detail {

/// The sampling grid: `cells` cells per axis over the box, m = cells + 1 nodes
/// per axis, node (i, j, k) at index i + m (j + m k).
struct SamplingGrid {
  SamplingGrid(const Box3& b, int c) : box(b), cells(c), m(c + 1) {}
  Box3 box;
  int cells;
  int m;

  std::size_t node_count() const { return static_cast<std::size_t>(m) * m * m; }
  int node_index(int i, int j, int k) const { return i + m * (j + m * k); }
  Point3 node_point(int i, int j, int k) const {
    return {coordinate(box.lo.x, box.hi.x, i), coordinate(box.lo.y, box.hi.y, j),
            coordinate(box.lo.z, box.hi.z, k)};
  }
  Point3 node_point(int node) const { return node_point(node % m, (node / m) % m, node / (m * m)); }
  /// The size of one cell along each axis.
  Point3 spacing() const { return (1.0 / cells) * (box.hi - box.lo); }

 private:
  double coordinate(double lo, double hi, int i) const {
    return i == cells ? hi : lo + (hi - lo) * i / cells;
  }
};

}  // namespace detail

namespace {

using detail::SamplingGrid;

/// The crossings of every grid edge whose end labels differ, and for each edge
/// (3 * lower node + axis) the index of its crossing, -1 for none.
struct GridCrossings {
  std::vector<Crossing> crossings;
  std::vector<int> edge_slot;
};

GridCrossings grid_crossings(const DomainOracle& oracle, const SamplingGrid& grid,
                             const std::vector<int>& labels) {
  GridCrossings out;
  out.edge_slot.assign(labels.size() * 3, -1);
  const int m = grid.m, cells = grid.cells;
  for (int k = 0; k < m; ++k) {
    for (int j = 0; j < m; ++j) {
      for (int i = 0; i < m; ++i) {
        const int from = grid.node_index(i, j, k);
        const int ni[3] = {i + 1, i, i}, nj[3] = {j, j + 1, j}, nk[3] = {k, k, k + 1};
        for (int axis = 0; axis < 3; ++axis) {
          if (ni[axis] > cells || nj[axis] > cells || nk[axis] > cells) continue;
          if (labels[from] == labels[grid.node_index(ni[axis], nj[axis], nk[axis])]) continue;
          const auto hit = oracle.intersect(grid.node_point(i, j, k),
                                            grid.node_point(ni[axis], nj[axis], nk[axis]));
          if (!hit) throw InternalError("implicit oracle: no crossing on a grid edge");
          out.edge_slot[3 * from + axis] = static_cast<int>(out.crossings.size());
          out.crossings.push_back({3 * from + axis, hit->point, hit->patch.value});
        }
      }
    }
  }
  return out;
}

/// Whether the eight nodes of grid cell (i, j, k) have one label: then none of
/// its edges has a crossing.
bool uniform_cell(const SamplingGrid& grid, const std::vector<int>& labels, int i, int j, int k) {
  const int first = labels[grid.node_index(i, j, k)];
  for (int c = 1; c < 8; ++c)
    if (labels[grid.node_index(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2))] != first)
      return false;
  return true;
}

/// Connected components: crossings of one patch on edges of a common cell are
/// joined (as in marching cubes). The members of each component, components in
/// order of their first crossing. (Cells whose nodes share a label, most of
/// them, are skipped on the labels: reading their twelve edges' slots took a
/// fifth of the oracle's set-up for the unit sphere.)
std::vector<std::vector<int>> connected_components(const SamplingGrid& grid,
                                                   const std::vector<int>& labels,
                                                   const GridCrossings& g) {
  const std::vector<Crossing>& crossings = g.crossings;
  UnionFind components(static_cast<int>(crossings.size()));
  const int cells = grid.cells;
  for (int k = 0; k < cells; ++k) {
    for (int j = 0; j < cells; ++j) {
      for (int i = 0; i < cells; ++i) {
        if (uniform_cell(grid, labels, i, j, k)) continue;
        int first_of_patch[12][2];
        int found = 0;
        for (int e = 0; e < 12; ++e) {
          const int axis = e / 4, d1 = e & 1, d2 = (e >> 1) & 1;
          const int node = axis == 0   ? grid.node_index(i, j + d1, k + d2)
                           : axis == 1 ? grid.node_index(i + d1, j, k + d2)
                                       : grid.node_index(i + d1, j + d2, k);
          const int slot = g.edge_slot[3 * node + axis];
          if (slot < 0) continue;
          int f = 0;
          while (f < found && first_of_patch[f][0] != crossings[slot].patch) ++f;
          if (f == found) {
            first_of_patch[found][0] = crossings[slot].patch;
            first_of_patch[found++][1] = slot;
          } else {
            components.unite(first_of_patch[f][1], slot);
          }
        }
      }
    }
  }
  std::vector<std::vector<int>> members;
  std::vector<int> component_of_root(crossings.size(), -1);
  for (int c = 0; c < static_cast<int>(crossings.size()); ++c) {
    int& comp = component_of_root[components.find(c)];
    if (comp < 0) {
      comp = static_cast<int>(members.size());
      members.emplace_back();
    }
    members[comp].push_back(c);
  }
  return members;
}

/// Adds to `points` (until it holds kMinPointsPerComponent + 1) crossings of
/// `patch` on the component's grid edges shifted by fractions of a cell: for a
/// component smaller than a cell.
void enrich_small_component(const DomainOracle& oracle, const SamplingGrid& grid,
                            const std::vector<Crossing>& crossings, const std::vector<int>& comp,
                            int patch, double tolerance, std::vector<Point3>& points) {
  Point3 spacing = grid.spacing();
  auto along_axis = [](Point3& p, int axis) -> double& {
    return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
  };
  for (double fraction : {0.25, 0.125, 0.0625, 0.03125}) {
    for (std::size_t c = 0; c < comp.size(); ++c) {
      if (static_cast<int>(points.size()) >= kMinPointsPerComponent + 1) break;
      const int node = crossings[comp[c]].edge / 3, axis = crossings[comp[c]].edge % 3;
      const Point3 p0 = grid.node_point(node);
      Point3 along;  // the grid edge
      along_axis(along, axis) = along_axis(spacing, axis);
      for (int shift = 0; shift < 4; ++shift) {
        const int other = (axis + 1 + shift / 2) % 3;
        Point3 offset;  // +-fraction of a cell along another axis
        along_axis(offset, other) = (shift % 2 ? -fraction : fraction) * along_axis(spacing, other);
        const auto hit = oracle.intersect(p0 + offset, p0 + along + offset);
        if (!hit || hit->patch.value != patch) continue;
        bool fresh = true;
        for (const Point3& q : points) fresh = fresh && distance(q, hit->point) > 1e3 * tolerance;
        if (fresh) points.push_back(hit->point);
      }
    }
  }
}

/// The initial points of one component: one crossing per kCrossingsPerPoint
/// (clamped to [kPointsPerComponent, kMaxPointsPerComponent]) spread out, then
/// enriched when the component is smaller than a cell.
std::vector<Point3> component_points(const DomainOracle& oracle, const SamplingGrid& grid,
                                     const std::vector<Crossing>& crossings,
                                     const std::vector<int>& comp, double tolerance) {
  const int patch = crossings[comp.front()].patch;
  std::vector<Point3> points;
  const int count = std::clamp(static_cast<int>(comp.size()) / kCrossingsPerPoint,
                               kPointsPerComponent, kMaxPointsPerComponent);
  for (int c : spread(crossings, comp, count)) points.push_back(crossings[c].point);
  enrich_small_component(oracle, grid, crossings, comp, patch, tolerance, points);
  return points;
}

/// Whether a node on the box's faces lies in a subdomain.
bool reaches_box(const SamplingGrid& grid, const std::vector<int>& labels) {
  const int m = grid.m;
  for (int k = 0; k < m; ++k) {
    for (int j = 0; j < m; ++j) {
      for (int i = 0; i < m; ++i) {
        const bool face = i == 0 || j == 0 || k == 0 || i == m - 1 || j == m - 1 || k == m - 1;
        if (face && labels[grid.node_index(i, j, k)] != 0) return true;
      }
    }
  }
  return false;
}

/// A domain far smaller than the grid's cells (a sphere of radius 1e-160,
/// found by fuzz/cli_campaign.py) shows its surface as one point: refinement
/// cannot start from fewer than four. (A domain that reaches the box is
/// refused with its own reason later: domain_file_limits.h.)
void check_surface_seen(std::size_t seeds, const SamplingGrid& grid,
                        const std::vector<int>& labels) {
  if (seeds < 4 && !reaches_box(grid, labels)) {
    throw InputError("the surface was found at fewer than 4 distinct points (" +
                     std::to_string(seeds) + ") on a grid of " + std::to_string(grid.cells) +
                     " cells per axis: the domain is far smaller than its box or its sizes");
  }
}

}  // namespace

std::vector<std::uint64_t> ImplicitOracle::grid_states(const detail::SamplingGrid& grid) const {
  const bool batched = std::any_of(used_.begin(), used_.end(), [this](int f) {
    return static_cast<std::size_t>(f) < options_.batch.size() && options_.batch[f];
  });
  if (!batched) return {};
  const int m = grid.m;
  std::vector<Point3> nodes;
  nodes.reserve(grid.node_count());
  for (int k = 0; k < m; ++k) {
    for (int j = 0; j < m; ++j) {
      for (int i = 0; i < m; ++i) nodes.push_back(grid.node_point(i, j, k));
    }
  }
  std::vector<std::uint64_t> states(nodes.size());
  for (std::size_t n = 0; n < nodes.size(); ++n)
    states[n] = box_.contains(nodes[n]) ? std::uint64_t{1} << kInBoxBit : 0;
  std::vector<double> values;
  for (const int f : used_) {
    values.clear();
    if (static_cast<std::size_t>(f) < options_.batch.size() && options_.batch[f]) {
      options_.batch[f](nodes, values);
      if (values.size() != nodes.size()) {
        throw InputError("function '" + function_names_[f] + "' returned " +
                         std::to_string(values.size()) + " values for " +
                         std::to_string(nodes.size()) + " points");
      }
    } else {
      for (const Point3& p : nodes) values.push_back(functions_[f](p));
    }
    for (std::size_t n = 0; n < nodes.size(); ++n) {
      if (values[n] < 0) states[n] |= std::uint64_t{1} << f;
    }
  }
  return states;
}

std::vector<int> ImplicitOracle::label_grid(const detail::SamplingGrid& grid) const {
  const int m = grid.m;
  const int n_sub = static_cast<int>(rules_.size());
  std::vector<int> labels(grid.node_count());
  std::vector<int> count(n_sub + 1, 0);
  const std::vector<std::uint64_t> states = grid_states(grid);
  for (int k = 0; k < m; ++k) {
    for (int j = 0; j < m; ++j) {
      for (int i = 0; i < m; ++i) {
        const int node = grid.node_index(i, j, k);
        const int l =
            states.empty() ? locate(grid.node_point(i, j, k)).label.value : label_of(states[node]);
        labels[node] = l;
        ++count[l];
      }
    }
  }
  for (int s = 1; s <= n_sub; ++s) {
    if (count[s] == 0) {
      throw InputError("subdomain '" + subdomain_infos_[s - 1].name +
                       "' matches no point of the box (sampled on a grid of " +
                       std::to_string(grid.cells) + " cells per axis)");
    }
  }
  return labels;
}

int ImplicitOracle::number_patches(const std::vector<int>& keys_found) {
  const int n_sub = static_cast<int>(rules_.size());
  const int n_pairs = n_sub * (n_sub + 1) / 2;
  const int n_keys = n_pairs * (static_cast<int>(functions_.size()) + 1);
  std::vector<char> found(n_keys, 0);
  for (const int key : keys_found) found[key] = 1;
  patch_of_key_.assign(n_keys, 0);
  key_of_patch_.assign(1, -1);
  for (int key = 0; key < n_keys; ++key) {
    if (!found[key]) continue;
    patch_of_key_[key] = static_cast<int>(key_of_patch_.size());
    key_of_patch_.push_back(key);
  }
  const int listed = static_cast<int>(key_of_patch_.size()) - 1;
  for (int key = 0; key < n_keys; ++key) {
    if (!found[key]) patch_of_key_[key] = listed + 1 + key;
  }
  features_.set_patch_count(static_cast<std::size_t>(listed));
  return listed;
}

void ImplicitOracle::name_patches(int listed) {
  // "a/b", with ":function" when several functions bound the same pair.
  const int n_sub = static_cast<int>(rules_.size());
  const int n_functions = static_cast<int>(functions_.size());
  auto sides = [&](int key) {
    const int rank = key / (n_functions + 1);
    int a = 0;
    while (rank >= (a + 1) * n_sub - a * (a + 1) / 2) ++a;
    const int b = rank - (a * n_sub - a * (a - 1) / 2) + a + 1;
    return std::make_pair(a, b);
  };
  for (int id = 1; id <= listed; ++id) {
    const int key = key_of_patch_[id];
    const auto [a, b] = sides(key);
    const int k = key % (n_functions + 1);
    int same_pair = 0;
    for (int other = 1; other <= listed; ++other)
      same_pair += sides(key_of_patch_[other]) == sides(key);
    std::string name =
        (a == 0 ? "outside" : subdomain_infos_[a - 1].name) + "/" + subdomain_infos_[b - 1].name;
    if (same_pair > 1) name += ":" + (k < n_functions ? function_names_[k] : std::string("box"));
    patches_.push_back({PatchId(id), name, SubdomainId(a), SubdomainId(b)});
  }
}

void ImplicitOracle::sample_box() {
  const SamplingGrid grid(box_, options_.sampling_resolution);
  const std::vector<int> labels = label_grid(grid);                                     // 1.
  GridCrossings g = grid_crossings(*this, grid, labels);                                // 2.
  const std::vector<std::vector<int>> members = connected_components(grid, labels, g);  // 3.
  // Number the patches found, in key order; crossings carried key + 1 so far.
  std::vector<int> keys;
  keys.reserve(g.crossings.size());
  for (const Crossing& c : g.crossings) keys.push_back(c.patch - 1);
  const int listed = number_patches(keys);
  for (Crossing& c : g.crossings) c.patch = patch_of_key_[c.patch - 1];
  for (const std::vector<int>& comp : members) {  // 4.
    features_.add_initial_points(PatchId(g.crossings[comp.front()].patch),
                                 component_points(*this, grid, g.crossings, comp, tolerance_));
  }
  check_surface_seen(features_.initial_point_count(), grid, labels);
  name_patches(listed);
}

}  // namespace rdmesh
