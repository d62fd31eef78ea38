#include "tet_smoothing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace rdmesh::detail {
namespace {

/// Tetrahedra within this many degrees of the worst one are raised together.
constexpr double kActive = 1.0;

}  // namespace

Star::Star(const TetTopology& topo, int v) : topo_(topo) {
  for (const int t : topo.tets_of(v)) {
    const Tet& q = topo.tet(t);
    tets_.push_back(q);
    slot_.push_back(static_cast<int>(std::find(q.begin(), q.end(), v) - q.begin()));
  }
}

double Star::quality(std::size_t i, const Point3& p) const {
  Point3 q[4];
  for (int k = 0; k < 4; ++k) q[k] = k == slot_[i] ? p : topo_.point(tets_[i][k]);
  return min_dihedral(q[0], q[1], q[2], q[3]);
}

double Star::min_quality(const Point3& p, double floor) const {
  double q = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < tets_.size(); ++i) {
    const double qi = quality(i, p);
    if (!(qi > floor)) return -1;
    q = std::min(q, qi);
  }
  for (std::size_t i = 0; i < tets_.size(); ++i) {
    Point3 c[4];
    for (int k = 0; k < 4; ++k) c[k] = k == slot_[i] ? p : topo_.point(tets_[i][k]);
    if (!positively_oriented(c[0], c[1], c[2], c[3])) return -1;
  }
  return q;
}

Point3 Star::ascent(const Point3& p, double h) const {
  double worst = std::numeric_limits<double>::infinity();
  std::vector<double> q(tets_.size());
  for (std::size_t i = 0; i < tets_.size(); ++i) worst = std::min(worst, q[i] = quality(i, p));
  std::vector<Point3> g;
  for (std::size_t i = 0; i < tets_.size(); ++i) {
    if (q[i] < worst + kActive) g.push_back(gradient(i, p, h));
  }
  Point3 x = g.front();
  for (int it = 0; it < 64; ++it) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < g.size(); ++i) {
      if (dot(x, g[i]) < dot(x, g[best])) best = i;
    }
    const Point3 d = g[best] - x;
    const double dd = dot(d, d);
    if (!(dd > 0) || dot(x, x) - dot(x, g[best]) <= 1e-12 * dot(x, x)) break;
    x = x + std::clamp(-dot(x, d) / dd, 0.0, 1.0) * d;
  }
  return x;
}

Point3 Star::gradient(std::size_t i, const Point3& p, double h) const {
  double g[3];
  for (int axis = 0; axis < 3; ++axis) {
    Point3 lo = p, hi = p;
    double* l = axis == 0 ? &lo.x : axis == 1 ? &lo.y : &lo.z;
    double* u = axis == 0 ? &hi.x : axis == 1 ? &hi.y : &hi.z;
    *l -= h;
    *u += h;
    g[axis] = (quality(i, hi) - quality(i, lo)) / (2 * h);
  }
  return {g[0], g[1], g[2]};
}

double climb(const Star& star, Point3& at, double q, double nearest) {
  ascend(
      star, at, nearest, [](const Point3& g) { return g; },
      [&](const Point3& p) {
        const double qp = star.min_quality(p, q);
        if (!(qp > q)) return false;
        at = p;
        q = qp;
        return true;
      });
  return q;
}

bool smooth_vertex(TetTopology& topo, int v) {
  if (topo.fixed(v) || topo.tets_of(v).empty()) return false;
  const int label = topo.label(topo.tets_of(v).front());
  double start = std::numeric_limits<double>::infinity();
  Point3 centroid{0, 0, 0};
  double nearest = std::numeric_limits<double>::infinity();
  int neighbours = 0;
  for (const int t : topo.tets_of(v)) {
    if (topo.label(t) != label) return false;
    start = std::min(start, topo.quality(t));
    for (const int w : topo.tet(t)) {
      if (w == v) continue;
      centroid = centroid + topo.point(w);
      nearest = std::min(nearest, distance(topo.point(w), topo.point(v)));
      ++neighbours;
    }
  }
  if (!(nearest > 0)) return false;
  const Star star(topo, v);
  Point3 at = topo.point(v);
  double q = start;
  // The centroid of the neighbours (each counted once per tetrahedron) first.
  const Point3 mean = (1.0 / neighbours) * centroid;
  if (const double qm = star.min_quality(mean, q); qm > q) {
    at = mean;
    q = qm;
  }
  q = climb(star, at, q, nearest);
  if (!(q > start)) return false;
  topo.move(v, at);
  return true;
}

}  // namespace rdmesh::detail
