#include "tet_flips.h"

#include <algorithm>
#include <array>
#include <limits>

namespace rdmesh::detail {
namespace {

constexpr int kMaxRing = 8;

/// The smallest dihedral angle of t, or -1 when t is not positively oriented.
double oriented_quality(const TetTopology& topo, const Tet& t) {
  const Point3 &p0 = topo.point(t[0]), &p1 = topo.point(t[1]), &p2 = topo.point(t[2]),
               &p3 = topo.point(t[3]);
  if (!positively_oriented(p0, p1, p2, p3)) return -1;
  return min_dihedral(p0, p1, p2, p3);
}

/// The ring of edge (a, b): r[0..n-1] such that (a, b, r[i], r[i+1]) is the
/// positive order of the i-th tetrahedron; false when the ring is not closed.
bool ring_of(const TetTopology& topo, int a, int b, const std::vector<int>& tets,
             std::vector<int>& ring) {
  const int n = static_cast<int>(tets.size());
  std::array<int, kMaxRing> from{}, to{};
  for (int i = 0; i < n; ++i) {
    const Tet& t = topo.tet(tets[i]);
    int x = -1, y = -1;
    for (const int v : t) {
      if (v == a || v == b) continue;
      (x < 0 ? x : y) = v;
    }
    if (!even_order(t, {a, b, x, y})) std::swap(x, y);
    from[i] = x;
    to[i] = y;
  }
  ring.assign(1, from[0]);
  int at = 0;
  for (int step = 1; step < n; ++step) {
    const int next =
        static_cast<int>(std::find(from.begin(), from.begin() + n, to[at]) - from.begin());
    if (next == n || next == 0) return false;
    at = next;
    ring.push_back(from[at]);
  }
  if (to[at] != ring[0]) return false;
  std::vector<int> sorted = ring;
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
}

}  // namespace

bool plan_edge_removal(const TetTopology& topo, int a, int b, LocalChange& change) {
  if (topo.constrained_edge(a, b)) return false;
  const std::vector<int> tets = topo.tets_with_edge(a, b);
  const int n = static_cast<int>(tets.size());
  if (n < 3 || n > kMaxRing) return false;
  const int label = topo.label(tets[0]);
  double before = std::numeric_limits<double>::infinity();
  for (const int t : tets) {
    if (topo.label(t) != label) return false;
    before = std::min(before, topo.quality(t));
  }
  std::vector<int> r;
  if (!ring_of(topo, a, b, tets, r)) return false;
  for (int i = 0; i < n; ++i) {
    if (topo.constrained_face(a, b, r[i])) return false;
  }

  // best[i][j]: the best smallest angle over the triangulations of ring
  // polygon r[i..j] (closed by the chord ij); split[i][j]: its apex.
  constexpr double kNone = std::numeric_limits<double>::infinity();
  double best[kMaxRing][kMaxRing];
  int split[kMaxRing][kMaxRing];
  double triangle[kMaxRing][kMaxRing][kMaxRing];  // by (i, k, j), i < k < j
  for (int i = 0; i < n; ++i)
    for (int k = i + 1; k < n; ++k)
      for (int j = k + 1; j < n; ++j) {
        const double qb = oriented_quality(topo, {r[i], r[k], r[j], b});
        const double qa = qb < 0 ? -1 : oriented_quality(topo, {r[i], r[j], r[k], a});
        triangle[i][k][j] = std::min(qa, qb);
      }
  for (int i = 0; i + 1 < n; ++i) best[i][i + 1] = kNone;
  for (int len = 2; len < n; ++len) {
    for (int i = 0; i + len < n; ++i) {
      const int j = i + len;
      best[i][j] = -1;
      split[i][j] = -1;
      for (int k = i + 1; k < j; ++k) {
        const double q = std::min({best[i][k], best[k][j], triangle[i][k][j]});
        if (q > best[i][j]) {
          best[i][j] = q;
          split[i][j] = k;
        }
      }
    }
  }
  if (!(best[0][n - 1] > before)) return false;

  change = {};
  change.removed = tets;
  change.label = label;
  change.before = before;
  change.after = best[0][n - 1];
  std::vector<std::array<int, 2>> todo{{0, n - 1}};
  while (!todo.empty()) {
    const auto [i, j] = todo.back();
    todo.pop_back();
    if (j - i < 2) continue;
    const int k = split[i][j];
    change.added.push_back({r[i], r[k], r[j], b});
    change.added.push_back({r[i], r[j], r[k], a});
    todo.push_back({k, j});
    todo.push_back({i, k});
  }
  return true;
}

bool plan_face_flip(const TetTopology& topo, int t, int i, LocalChange& change) {
  const Tet& q = topo.tet(t);
  const int d = q[i];
  int p = q[(i + 1) & 3], r1 = q[(i + 2) & 3], r2 = q[(i + 3) & 3];
  if (topo.constrained_face(p, r1, r2)) return false;
  const int u = topo.across(t, p, r1, r2);
  if (u < 0 || topo.label(u) != topo.label(t)) return false;
  int e = -1;
  for (const int v : topo.tet(u)) {
    if (v != p && v != r1 && v != r2) e = v;
  }
  if (!even_order(topo.tet(u), {p, r1, r2, e})) std::swap(r1, r2);
  // (p, r1, r2, e) is positive: the new tetrahedra turn around de that way.
  const std::array<Tet, 3> added{{{d, e, p, r1}, {d, e, r1, r2}, {d, e, r2, p}}};
  double after = std::numeric_limits<double>::infinity();
  for (const Tet& n : added) after = std::min(after, oriented_quality(topo, n));
  const double before = std::min(topo.quality(t), topo.quality(u));
  if (!(after > before)) return false;
  change = {};
  change.removed = {t, u};
  change.added.assign(added.begin(), added.end());
  change.label = topo.label(t);
  change.before = before;
  change.after = after;
  return true;
}

void apply(TetTopology& topo, const LocalChange& change) {
  for (const int t : change.removed) topo.remove(t);
  for (const Tet& t : change.added) topo.add(t, change.label);
}

}  // namespace rdmesh::detail
