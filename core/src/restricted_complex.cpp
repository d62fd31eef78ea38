// The restricted complex of RR-7912 section 3, maintained cell by cell:
//  - D|O: a cell belongs to the mesh when its circumcenter lies in a subdomain
//    (its label, from the oracle's locate());
//  - D|S_k: a facet belongs to D|S_k when its dual Voronoi edge crosses patch
//    S_k. The edge joins the circumcenters of the two incident cells, so it
//    crosses the boundary when their labels differ; the crossing point, found
//    by the oracle, is the center of the facet's surface Delaunay ball.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "refiner.h"
#include "simplex_geometry.h"

namespace rdmesh::detail {

void Refiner::stamp_new(CellInfo& c) {
  c.stamp = next_stamp_++;
  if ((c.stamp >> 6) >= live_.size()) live_.resize(2 * live_.size() + 1024, 0);
  live_[c.stamp >> 6] |= std::uint64_t{1} << (c.stamp & 63);
}

void Refiner::kill(CellInfo& c) {
  live_[c.stamp >> 6] &= ~(std::uint64_t{1} << (c.stamp & 63));
  c.stamp = 0;
}

void Refiner::init_cell(Cell_handle c, Cell_handle from) {
  CellInfo& info = c->info();
  stamp_new(info);
  info.facet_patch = {0, 0, 0, 0};
  info.crossing_facet = -1;
  if (tr_.is_infinite(c)) {
    info.label = kOutside.value;
    return;
  }
  // The orthosphere (the circumsphere when no vertex carries a protecting
  // ball): its center is the cell's dual Voronoi vertex, its squared radius
  // the power of that center (negative inside overlapping balls).
  std::array<Point3, 4> p;
  std::array<double, 4> w;
  for (int k = 0; k < 4; ++k) {
    p[k] = to_point3(c->vertex(k)->point());
    w[k] = c->vertex(k)->point().weight();
  }
  info.circumcenter = tet_orthocenter(p, w);
  info.squared_radius = squared_norm(info.circumcenter - p[0]) - w[0];
  const bool finite_center = is_finite(info.circumcenter);
  // Surface only: no cell is in the mesh, labels are never needed.
  if (!finite_center || options_.surface_only) {
    info.label = kOutside.value;
    return;
  }
  const bool known = from != Cell_handle() && from->info().stamp != 0 && !tr_.is_infinite(from) &&
                     is_finite(from->info().circumcenter);
  if (!known) {
    info.label = oracle_.locate(info.circumcenter).value;
    return;
  }
  // [circumcenter, from's] is the dual edge of the facet between the two
  // cells: a crossing found on it serves that facet too (update_facet()).
  const DomainOracle::Located l = oracle_.locate_across(
      info.circumcenter, from->info().circumcenter, SubdomainId{from->info().label});
  info.label = l.label.value;
  if (l.crossing && l.label.value != from->info().label) {
    const int i = c->index(from);
    info.crossing_facet = static_cast<std::int8_t>(i);
    info.crossing_with = from->info().stamp;
    info.facet_patch[i] = l.crossing->patch.value;
    info.surface_center[i] = l.crossing->point;
  }
}

std::optional<SurfaceHit> Refiner::take_crossing(Cell_handle c, int i, Cell_handle n) {
  CellInfo& info = c->info();
  if (info.crossing_facet != i) return std::nullopt;
  info.crossing_facet = -1;
  if (info.crossing_with != n->info().stamp || info.facet_patch[i] == 0) return std::nullopt;
  return SurfaceHit{info.surface_center[i], PatchId{info.facet_patch[i]}};
}

bool Refiner::dual_segment(Cell_handle c, int i, Point3& a, Point3& b) const {
  // The dual of facet (c, i) lies on the line through the facet's orthocenter
  // perpendicular to it, between the orthocenters of its two cells (or from the
  // finite one to infinity for a hull facet). Parametrizing that line from the
  // facet's own orthocenter keeps every digit even when a nearly flat cell's
  // center is 1e16 away; beyond the clip box the domain is empty, so only the
  // part inside it goes to the oracle.
  const Cell_handle n = c->neighbor(i);
  // A facet through the infinite vertex (both its cells infinite) has no dual
  // edge in the finite space.
  if (tr_.is_infinite(c) && tr_.is_infinite(n)) return false;
  const Vertex_handle v[3] = {c->vertex((i + 1) & 3), c->vertex((i + 2) & 3),
                              c->vertex((i + 3) & 3)};
  const Point3 q[3] = {to_point3(v[0]->point()), to_point3(v[1]->point()),
                       to_point3(v[2]->point())};
  const double w[3] = {v[0]->point().weight(), v[1]->point().weight(), v[2]->point().weight()};
  Point3 normal = cross(q[1] - q[0], q[2] - q[0]);
  const double len = norm(normal);
  if (!(len > 0)) return false;
  normal = (1 / len) * normal;
  const Point3 origin = (w[0] == 0 && w[1] == 0 && w[2] == 0)
                            ? triangle_circumcenter(q[0], q[1], q[2])
                            : triangle_orthocenter(q[0], w[0], q[1], w[1], q[2], w[2]);
  if (!std::isfinite(origin.x + origin.y + origin.z)) return false;
  // A cell's end of the edge: its center's coordinate along the line, or an
  // infinite one (away from the cell's opposite vertex) for the infinite cell.
  auto end_of = [&](Cell_handle cell, Cell_handle other) {
    if (tr_.is_infinite(cell)) {
      const Point3 opposite = to_point3(other->vertex(other->index(cell))->point());
      return dot(normal, opposite - q[0]) > 0 ? -std::numeric_limits<double>::infinity()
                                              : std::numeric_limits<double>::infinity();
    }
    return dot(cell->info().circumcenter - origin, normal);
  };
  const double sc = end_of(c, n), sn = end_of(n, c);
  if (std::isnan(sc) || std::isnan(sn)) return false;  // a flat cell without a center
  double t0 = -std::numeric_limits<double>::infinity(),
         t1 = std::numeric_limits<double>::infinity();
  if (!clip_line(origin, normal, clip_box_, t0, t1)) return false;
  const double lo = std::max(std::min(sc, sn), t0), hi = std::min(std::max(sc, sn), t1);
  if (!(lo <= hi)) return false;
  a = origin + (sc <= sn ? lo : hi) * normal;
  b = origin + (sc <= sn ? hi : lo) * normal;
  return true;
}

void Refiner::update_facet(Cell_handle c, int i) {
  const Cell_handle n = c->neighbor(i);
  const int j = n->index(c);
  std::optional<SurfaceHit> hit = take_crossing(c, i, n);
  if (!hit) hit = take_crossing(n, j, c);
  c->info().facet_patch[i] = 0;
  n->info().facet_patch[j] = 0;
  // Equal labels: no crossing (or an even number, which refinement removes).
  // Surface only, every dual edge is asked: an open patch has no sides.
  if (c->info().label == n->info().label && !options_.surface_only) return;

  if (!hit) {
    Point3 a, b;
    if (!dual_segment(c, i, a, b)) return;
    hit = oracle_.intersect(a, b);
    if (!hit) return;
  }
  c->info().facet_patch[i] = hit->patch.value;
  c->info().surface_center[i] = hit->point;
  n->info().facet_patch[j] = hit->patch.value;
  n->info().surface_center[j] = hit->point;

  const double badness = facet_badness(c, i);
  if (badness > 0) facet_queue_.push({badness, c, c->info().stamp, i});
}

double Refiner::facet_badness(Cell_handle c, int i) const {
  const int patch = c->info().facet_patch[i];
  if (patch == 0) return 0.0;
  const Vertex_handle v[3] = {c->vertex((i + 1) & 3), c->vertex((i + 2) & 3),
                              c->vertex((i + 3) & 3)};
  // R3: every vertex of a facet of D|S_k must lie on S_k (or on its boundary curves).
  for (const Vertex_handle& vh : v) {
    if (!on_patch(vh->info(), patch)) return 1e300;
  }
  const Point3 p[3] = {to_point3(v[0]->point()), to_point3(v[1]->point()),
                       to_point3(v[2]->point())};
  const Point3 center = c->info().surface_center[i];
  double badness = 0.0;
  // R4.1: surface Delaunay ball radius against the sizing field.
  const double r2 = facet_power(c, i, center);
  const double sigma = criteria_.facet_size(center);
  if (r2 > sigma * sigma) badness = std::max(badness, r2 / (sigma * sigma));
  // R4.2: shape, as a minimum angle: min edge^2 >= 4 sin^2(angle) R^2, with R
  // the triangle's circumradius. Next to a protecting ball (a weighted vertex)
  // R is the surface ball's radius instead, as in the paper's R4.2: its center,
  // the refinement point, is then at least R from every unweighted vertex, so
  // refining a bad facet never inserts a point closer than its shortest edge.
  const double w[3] = {v[0]->point().weight(), v[1]->point().weight(), v[2]->point().weight()};
  const bool weighted = w[0] != 0 || w[1] != 0 || w[2] != 0;
  const Point3 tc = triangle_circumcenter(p[0], p[1], p[2]);
  const double shape_r2 = weighted ? r2 : squared_norm(p[0] - tc);
  const double e2 = min_squared_edge(p[0], p[1], p[2]);
  if (!(e2 >= facet_shape_bound_ * shape_r2)) {
    badness = std::max(badness, e2 > 0 ? facet_shape_bound_ * shape_r2 / e2 : 1e200);
  }
  // Approximation: the ball center on the patch is close to the facet's plane
  // (its distance to the facet's orthocenter, the foot of the dual edge; the
  // circumcenter when no vertex is weighted).
  const Point3 oc = weighted ? triangle_orthocenter(p[0], w[0], p[1], w[1], p[2], w[2]) : tc;
  const double d2 = squared_norm(oc - center);
  const double dmax = criteria_.facet_distance(center), dmax2 = dmax * dmax;
  if (!(d2 <= dmax2)) badness = std::max(badness, std::isfinite(d2) ? d2 / dmax2 : 1e200);
  return badness;
}

double Refiner::facet_power(Cell_handle c, int i, const Point3& x) const {
  const Weighted_point& q = c->vertex((i + 1) & 3)->point();
  return squared_norm(x - to_point3(q)) - q.weight();
}

bool Refiner::ball_conflict(Cell_handle c, int i) {
  const int patch = c->info().facet_patch[i];
  const Point3 center = c->info().surface_center[i];
  for (int k = 1; k < 4; ++k) {
    const Vertex_handle v = c->vertex((i + k) & 3);
    const double w = v->point().weight();
    if (w == 0 || on_patch(v->info(), patch)) continue;
    // The surface center is on the sphere of the facet's orthoball, so it lies
    // near or in this ball only when the ball reaches the patch (an early,
    // coarse facet far from the ball is refined as usual).
    if (squared_norm(center - to_point3(v->point())) > 1.5 * w) continue;
    add_conflict(ball_of(v->info()));
    return true;
  }
  return false;
}

BallRef Refiner::ball_of(const VertexInfo& info) const {
  BallRef ref;
  if (info.dim == FeatureDim::kCorner) {
    ref.corner = info.feature - 1;
  } else {
    const std::vector<BallSample>& s = plan_->curves[info.feature - 1].samples;
    const auto it = std::lower_bound(s.begin(), s.end(), info.t,
                                     [](const BallSample& b, double t) { return b.t < t; });
    ref.curve = info.feature - 1;
    ref.index = static_cast<int>(it - s.begin());
  }
  return ref;
}

void Refiner::add_conflict(const BallRef& ref) {
  for (BallRef& b : conflicts_) {
    if (b.curve == ref.curve && b.index == ref.index && b.corner == ref.corner) {
      b.factor = std::min(b.factor, ref.factor);
      return;
    }
  }
  conflicts_.push_back(ref);
}

void Refiner::overlap_conflict(Cell_handle c, int i) {
  auto info_of = [&](int j) -> const CurveInfo& { return curves_[j].info; };
  // The overlapping pairs of unrelated balls among the facet's vertices.
  std::array<BallRef, 6> pairs;
  int n = 0;
  for (int x = 1; x < 4; ++x) {
    const Vertex_handle a = c->vertex((i + x) & 3);
    const double wa = a->point().weight();
    if (wa == 0) continue;
    const BallRef ball_a = ball_of(a->info());
    for (int y = x + 1; y < 4; ++y) {
      const Vertex_handle b = c->vertex((i + y) & 3);
      const double wb = b->point().weight();
      if (wb == 0) continue;
      const BallRef ball_b = ball_of(b->info());
      if (related_balls(ball_a, ball_b, info_of)) continue;
      const double ra = std::sqrt(wa), rb = std::sqrt(wb);
      const double need = ProtectionPlanner::disjoint_distance(ra, rb);
      const double dist = distance(to_point3(a->point()), to_point3(b->point()));
      if (dist >= need) continue;
      // Down to disjoint at once (B2 for related balls), rather than by halves.
      pairs[n] = ball_a, pairs[n + 1] = ball_b;
      pairs[n].factor = pairs[n + 1].factor = std::min(0.5, 0.95 * dist / need);
      n += 2;
    }
  }
  if (n == 0) return;
  // The surface within the facet distance of the centroid, along the normal.
  const Point3 p[3] = {to_point3(c->vertex((i + 1) & 3)->point()),
                       to_point3(c->vertex((i + 2) & 3)->point()),
                       to_point3(c->vertex((i + 3) & 3)->point())};
  const Point3 normal = cross(p[1] - p[0], p[2] - p[0]);
  const double len = norm(normal);
  if (!(len > 0)) return;
  const Point3 g = (1.0 / 3) * (p[0] + p[1] + p[2]);
  const Point3 reach = (1.5 * criteria_.facet_distance(g) / len) * normal;
  if (oracle_.intersect(g - reach, g + reach)) return;
  for (int k = 0; k < n; ++k) add_conflict(pairs[k]);
}

bool Refiner::on_patch(const VertexInfo& v, int patch) const {
  auto contains = [patch](const std::vector<int>& patches) {
    return std::find(patches.begin(), patches.end(), patch) != patches.end();
  };
  switch (v.dim) {
    case FeatureDim::kPatch:
      return v.feature == patch;
    case FeatureDim::kCurve:
      return contains(curve_patches_[v.feature - 1]);
    case FeatureDim::kCorner:
      return contains(corner_patches_[v.feature - 1]);
    case FeatureDim::kVolume:
      return false;
  }
  return false;
}

double Refiner::cell_badness(Cell_handle c) const {
  const CellInfo& info = c->info();
  if (info.label == kOutside.value || tr_.is_infinite(c)) return 0.0;
  double badness = 0.0;
  // R5.1: Delaunay ball radius against the sizing field.
  const double sigma = criteria_.cell_size(info.circumcenter);
  if (info.squared_radius > sigma * sigma) badness = info.squared_radius / (sigma * sigma);
  // R5.2: radius-edge ratio <= beta_3.
  const double e2 =
      min_squared_edge(to_point3(c->vertex(0)->point()), to_point3(c->vertex(1)->point()),
                       to_point3(c->vertex(2)->point()), to_point3(c->vertex(3)->point()));
  const double limit = cell_shape_bound_sq_ * e2;
  if (info.squared_radius > limit) badness = std::max(badness, info.squared_radius / limit);
  return badness;
}

}  // namespace rdmesh::detail
