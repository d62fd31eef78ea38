// ImplicitOracle::sample_box: discovers the patches, their connected components
// and initial points on a regular grid over the bounding box.
//
// 1. Label every grid node with locate().
// 2. Every grid edge whose end labels differ is a crossing: intersect() on it
//    gives a point and the patch actually crossed.
// 3. Two crossings of the same patch on edges of a common grid cell belong to
//    the same connected component (union-find), as in marching cubes.
// 4. Each component contributes one crossing per kCrossingsPerPoint (at least
//    kPointsPerComponent, at most kMaxPointsPerComponent), chosen by
//    farthest-point sampling (spread out, deterministic). A handful of points is
//    not enough: the Delaunay triangulation of 8 points on a torus has no
//    Voronoi vertex inside the tube, so the refinement would see no restricted
//    facet at all; a sample spaced at a few grid cells captures the topology. A component with
//    fewer than three crossings (smaller than a grid cell) is enriched with crossings of
//    grid-parallel segments shifted by fractions of a cell.

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

/// Indices of up to `count` crossings of `members`, spread by farthest-point sampling.
std::vector<int> spread(const std::vector<Crossing>& crossings, const std::vector<int>& members,
                        int count) {
  std::vector<int> chosen{members.front()};
  std::vector<double> dist(members.size(), std::numeric_limits<double>::infinity());
  while (static_cast<int>(chosen.size()) < std::min<int>(count, members.size())) {
    const Point3 last = crossings[chosen.back()].point;
    std::size_t far = 0;
    for (std::size_t m = 0; m < members.size(); ++m) {
      dist[m] = std::min(dist[m], distance(crossings[members[m]].point, last));
      if (dist[m] > dist[far]) far = m;
    }
    if (!(dist[far] > 0)) break;
    chosen.push_back(members[far]);
  }
  return chosen;
}

}  // namespace

template <class NodePoint>
std::vector<std::uint64_t> ImplicitOracle::grid_states(int m, const NodePoint& node_point) const {
  const bool batched = std::any_of(used_.begin(), used_.end(), [this](int f) {
    return static_cast<std::size_t>(f) < options_.batch.size() && options_.batch[f];
  });
  if (!batched) return {};
  std::vector<Point3> nodes;
  nodes.reserve(static_cast<std::size_t>(m) * m * m);
  for (int k = 0; k < m; ++k) {
    for (int j = 0; j < m; ++j) {
      for (int i = 0; i < m; ++i) nodes.push_back(node_point(i, j, k));
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

void ImplicitOracle::sample_box() {
  const int cells = options_.sampling_resolution;
  const int m = cells + 1;
  const int n_sub = static_cast<int>(rules_.size());
  auto coordinate = [cells](double lo, double hi, int i) {
    return i == cells ? hi : lo + (hi - lo) * i / cells;
  };
  auto node_point = [&](int i, int j, int k) {
    return Point3{coordinate(box_.lo.x, box_.hi.x, i), coordinate(box_.lo.y, box_.hi.y, j),
                  coordinate(box_.lo.z, box_.hi.z, k)};
  };
  auto node_index = [m](int i, int j, int k) { return i + m * (j + m * k); };

  std::vector<int> labels(static_cast<std::size_t>(m) * m * m);
  std::vector<int> count(n_sub + 1, 0);
  const std::vector<std::uint64_t> states = grid_states(m, node_point);
  for (int k = 0; k < m; ++k) {
    for (int j = 0; j < m; ++j) {
      for (int i = 0; i < m; ++i) {
        const int node = node_index(i, j, k);
        const int l =
            states.empty() ? locate(node_point(i, j, k)).label.value : label_of(states[node]);
        labels[node] = l;
        ++count[l];
      }
    }
  }
  for (int s = 1; s <= n_sub; ++s) {
    if (count[s] == 0) {
      throw InputError("subdomain '" + subdomain_infos_[s - 1].name +
                       "' matches no point of the box (sampled on a grid of " +
                       std::to_string(cells) + " cells per axis)");
    }
  }

  // Crossings on grid edges.
  std::vector<Crossing> crossings;
  std::vector<int> edge_slot(labels.size() * 3, -1);
  for (int k = 0; k < m; ++k) {
    for (int j = 0; j < m; ++j) {
      for (int i = 0; i < m; ++i) {
        const int from = node_index(i, j, k);
        const int ni[3] = {i + 1, i, i}, nj[3] = {j, j + 1, j}, nk[3] = {k, k, k + 1};
        for (int axis = 0; axis < 3; ++axis) {
          if (ni[axis] > cells || nj[axis] > cells || nk[axis] > cells) continue;
          if (labels[from] == labels[node_index(ni[axis], nj[axis], nk[axis])]) continue;
          const auto hit = intersect(node_point(i, j, k), node_point(ni[axis], nj[axis], nk[axis]));
          if (!hit) throw InternalError("implicit oracle: no crossing on a grid edge");
          edge_slot[3 * from + axis] = static_cast<int>(crossings.size());
          crossings.push_back({3 * from + axis, hit->point, hit->patch.value});
        }
      }
    }
  }

  // Connected components: crossings of one patch on edges of a common cell.
  UnionFind components(static_cast<int>(crossings.size()));
  for (int k = 0; k < cells; ++k) {
    for (int j = 0; j < cells; ++j) {
      for (int i = 0; i < cells; ++i) {
        int first_of_patch[12][2];
        int found = 0;
        for (int e = 0; e < 12; ++e) {
          const int axis = e / 4, d1 = e & 1, d2 = (e >> 1) & 1;
          const int node = axis == 0   ? node_index(i, j + d1, k + d2)
                           : axis == 1 ? node_index(i + d1, j, k + d2)
                                       : node_index(i + d1, j + d2, k);
          const int slot = edge_slot[3 * node + axis];
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

  // Members of each component, components in order of their first crossing.
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

  // Number the patches found, in key order; crossings carried key + 1 so far.
  const int n_pairs = n_sub * (n_sub + 1) / 2;
  const int n_keys = n_pairs * (static_cast<int>(functions_.size()) + 1);
  std::vector<char> found(n_keys, 0);
  for (const Crossing& c : crossings) found[c.patch - 1] = 1;
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
  for (Crossing& c : crossings) c.patch = patch_of_key_[c.patch - 1];
  features_.set_patch_count(static_cast<std::size_t>(listed));
  const Point3 spacing = (1.0 / cells) * (box_.hi - box_.lo);
  for (const std::vector<int>& comp : members) {
    const int patch = crossings[comp.front()].patch;
    std::vector<Point3> points;
    const int count = std::clamp(static_cast<int>(comp.size()) / kCrossingsPerPoint,
                                 kPointsPerComponent, kMaxPointsPerComponent);
    for (int c : spread(crossings, comp, count)) points.push_back(crossings[c].point);
    // Enrich components smaller than a cell with crossings of shifted grid edges.
    for (double fraction : {0.25, 0.125, 0.0625, 0.03125}) {
      for (std::size_t c = 0; c < comp.size(); ++c) {
        if (static_cast<int>(points.size()) >= kMinPointsPerComponent + 1) break;
        const int node = crossings[comp[c]].edge / 3, axis = crossings[comp[c]].edge % 3;
        const Point3 p0 = node_point(node % m, (node / m) % m, node / (m * m));
        const Point3 along = axis == 0   ? Point3{spacing.x, 0, 0}
                             : axis == 1 ? Point3{0, spacing.y, 0}
                                         : Point3{0, 0, spacing.z};
        for (int shift = 0; shift < 4; ++shift) {
          const int other = (axis + 1 + shift / 2) % 3;
          Point3 offset;
          (other == 0   ? offset.x
           : other == 1 ? offset.y
                        : offset.z) =
              (shift % 2 ? -fraction : fraction) * (other == 0   ? spacing.x
                                                    : other == 1 ? spacing.y
                                                                 : spacing.z);
          const auto hit = intersect(p0 + offset, p0 + along + offset);
          if (!hit || hit->patch.value != patch) continue;
          bool fresh = true;
          for (const Point3& q : points)
            fresh = fresh && distance(q, hit->point) > 1e3 * tolerance_;
          if (fresh) points.push_back(hit->point);
        }
      }
    }
    features_.add_initial_points(PatchId(patch), points);
  }
  // A domain far smaller than the grid's cells (a sphere of radius 1e-160,
  // found by fuzz/cli_campaign.py) shows its surface as one point: refinement
  // cannot start from fewer than four.
  // (A domain that reaches the box is refused with its own reason later:
  // domain_file_limits.h.)
  const std::size_t seeds = features_.initial_point_count();
  bool reaches_box = false;
  for (int k = 0; k < m && !reaches_box; ++k) {
    for (int j = 0; j < m && !reaches_box; ++j) {
      for (int i = 0; i < m && !reaches_box; ++i) {
        const bool face = i == 0 || j == 0 || k == 0 || i == m - 1 || j == m - 1 || k == m - 1;
        reaches_box = face && labels[node_index(i, j, k)] != 0;
      }
    }
  }
  if (seeds < 4 && !reaches_box) {
    throw InputError("the surface was found at fewer than 4 distinct points (" +
                     std::to_string(seeds) + ") on a grid of " + std::to_string(cells) +
                     " cells per axis: the domain is far smaller than its box or its sizes");
  }

  // Names: "a/b", with ":function" when several functions bound the same pair.
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

}  // namespace rdmesh
