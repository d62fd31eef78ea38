#include "tet_insertion.h"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>
#include <vector>

#include "tet_smoothing.h"

namespace rdmesh::detail {
namespace {

using Face = std::array<int, 3>;

Face sorted_face(const Tet& t, int i) {
  Face f{t[(i + 1) & 3], t[(i + 2) & 3], t[(i + 3) & 3]};
  std::sort(f.begin(), f.end());
  return f;
}

}  // namespace

bool plan_insertion(const TetTopology& topo, int t, int levels, int new_vertex, Point3& where,
                    LocalChange& change) {
  const int label = topo.label(t);
  std::vector<int> cavity{t};
  for (std::size_t from = 0, level = 0; level < static_cast<std::size_t>(levels); ++level) {
    const std::size_t to = cavity.size();
    for (; from < to; ++from) {
      const Tet q = topo.tet(cavity[from]);
      for (int i = 0; i < 4; ++i) {
        const int a = q[(i + 1) & 3], b = q[(i + 2) & 3], c = q[(i + 3) & 3];
        if (topo.constrained_face(a, b, c)) continue;
        const int u = topo.across(cavity[from], a, b, c);
        if (u >= 0 && topo.label(u) == label &&
            std::find(cavity.begin(), cavity.end(), u) == cavity.end()) {
          cavity.push_back(u);
        }
      }
    }
  }
  if (cavity.size() < 2) return false;
  // Faces of the cavity: (sorted face, tet, index); those seen once bound it.
  std::vector<std::pair<Face, std::array<int, 2>>> faces;
  for (const int c : cavity) {
    for (int i = 0; i < 4; ++i) faces.push_back({sorted_face(topo.tet(c), i), {c, i}});
  }
  std::sort(faces.begin(), faces.end());
  std::vector<std::array<int, 2>> boundary;
  std::vector<std::array<int, 2>> boundary_edges;
  std::vector<int> boundary_vertices;
  for (std::size_t k = 0; k < faces.size();) {
    std::size_t n = 1;
    while (k + n < faces.size() && faces[k + n].first == faces[k].first) ++n;
    const Face& f = faces[k].first;
    if (n == 1) {
      boundary.push_back(faces[k].second);
      for (int e = 0; e < 3; ++e)
        boundary_edges.push_back({std::min(f[e], f[(e + 1) % 3]), std::max(f[e], f[(e + 1) % 3])});
      boundary_vertices.insert(boundary_vertices.end(), f.begin(), f.end());
    } else if (topo.constrained_face(f[0], f[1], f[2])) {
      return false;  // it would disappear inside the cavity
    }
    k += n;
  }
  std::sort(boundary_edges.begin(), boundary_edges.end());
  std::sort(boundary_vertices.begin(), boundary_vertices.end());
  double before = std::numeric_limits<double>::infinity();
  std::vector<Point3> candidates;
  Point3 all{0, 0, 0};
  int count = 0;
  for (const int c : cavity) {
    const Tet& r = topo.tet(c);
    before = std::min(before, topo.quality(c));
    Point3 g{0, 0, 0};
    for (int i = 0; i < 4; ++i) {
      g = g + topo.point(r[i]);
      all = all + topo.point(r[i]);
      ++count;
      if (!std::binary_search(boundary_vertices.begin(), boundary_vertices.end(), r[i]))
        return false;
      for (int j = i + 1; j < 4; ++j) {
        const std::array<int, 2> e{std::min(r[i], r[j]), std::max(r[i], r[j])};
        if (!std::binary_search(boundary_edges.begin(), boundary_edges.end(), e) &&
            topo.constrained_edge(e[0], e[1])) {
          return false;
        }
      }
    }
    candidates.push_back(0.25 * g);
  }
  candidates.push_back((1.0 / count) * all);

  // The best valid candidate, then a climb of the new vertex's star from it.
  std::vector<Tet> added;
  std::vector<int> slots;
  for (const auto& [c, i] : boundary) {
    Tet n = topo.tet(c);
    n[i] = new_vertex;
    added.push_back(n);
    slots.push_back(i);
  }
  const Star star(topo, added, slots);
  double best = 0;
  int chosen = -1;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const double q = star.min_quality(candidates[k], best);
    if (q > best) {
      best = q;
      chosen = static_cast<int>(k);
    }
  }
  if (chosen < 0) return false;
  where = candidates[chosen];
  double nearest = std::numeric_limits<double>::infinity();
  for (const int v : boundary_vertices) nearest = std::min(nearest, distance(topo.point(v), where));
  best = climb(star, where, best, nearest);
  if (!(best > before)) return false;
  change = {};
  change.removed = cavity;
  change.label = label;
  change.before = before;
  change.after = best;
  change.added = std::move(added);
  return true;
}

}  // namespace rdmesh::detail
