// The restricted complex of RR-7912 section 3, maintained cell by cell:
//  - D|O: a cell belongs to the mesh when its circumcenter lies in a subdomain
//    (its label, from the oracle's locate());
//  - D|S_k: a facet belongs to D|S_k when its dual Voronoi edge crosses patch
//    S_k. The edge joins the circumcenters of the two incident cells, so it
//    crosses the boundary when their labels differ; the crossing point, found
//    by the oracle, is the center of the facet's surface Delaunay ball.
#include <algorithm>
#include <cmath>
#include <limits>

#include "refiner.h"
#include "simplex_geometry.h"

namespace rdmesh::detail {

void Refiner::init_cell(Cell_handle c) {
  CellInfo& info = c->info();
  info.stamp = next_stamp_++;
  info.facet_patch = {0, 0, 0, 0};
  if (tr_.is_infinite(c)) {
    info.label = kOutside.value;
    return;
  }
  const Point3 p0 = to_point3(c->vertex(0)->point());
  info.circumcenter = tet_circumcenter(p0, to_point3(c->vertex(1)->point()),
                                       to_point3(c->vertex(2)->point()),
                                       to_point3(c->vertex(3)->point()));
  info.squared_radius = squared_norm(info.circumcenter - p0);
  const bool finite_center = std::isfinite(info.circumcenter.x) &&
                             std::isfinite(info.circumcenter.y) &&
                             std::isfinite(info.circumcenter.z);
  info.label = finite_center ? oracle_.locate(info.circumcenter).value : kOutside.value;
}

bool Refiner::dual_segment(Cell_handle c, int i, Point3& a, Point3& b) const {
  const Cell_handle n = c->neighbor(i);
  if (!tr_.is_infinite(c) && !tr_.is_infinite(n)) {
    a = c->info().circumcenter;
    b = n->info().circumcenter;
    return true;
  }
  // A hull facet: its dual is the ray from the finite cell's circumcenter,
  // perpendicular to the facet, away from the finite cell.
  const Cell_handle f = tr_.is_infinite(c) ? n : c;
  const int k = tr_.is_infinite(c) ? n->index(c) : i;
  const Point3 q0 = to_point3(f->vertex((k + 1) & 3)->point());
  const Point3 q1 = to_point3(f->vertex((k + 2) & 3)->point());
  const Point3 q2 = to_point3(f->vertex((k + 3) & 3)->point());
  Point3 dir = cross(q1 - q0, q2 - q0);
  if (dot(dir, to_point3(f->vertex(k)->point()) - q0) > 0) dir = -1.0 * dir;
  const Point3 origin = f->info().circumcenter;
  // Slab clipping: the parameter where the ray leaves the clip box.
  double t_exit = std::numeric_limits<double>::infinity();
  const double o[3] = {origin.x, origin.y, origin.z};
  const double d[3] = {dir.x, dir.y, dir.z};
  const double lo[3] = {clip_box_.lo.x, clip_box_.lo.y, clip_box_.lo.z};
  const double hi[3] = {clip_box_.hi.x, clip_box_.hi.y, clip_box_.hi.z};
  for (int axis = 0; axis < 3; ++axis) {
    if (d[axis] > 0) t_exit = std::min(t_exit, (hi[axis] - o[axis]) / d[axis]);
    if (d[axis] < 0) t_exit = std::min(t_exit, (lo[axis] - o[axis]) / d[axis]);
  }
  if (!(t_exit > 0) || !std::isfinite(t_exit)) return false;
  a = origin;
  b = origin + t_exit * dir;
  return true;
}

void Refiner::update_facet(Cell_handle c, int i) {
  const Cell_handle n = c->neighbor(i);
  const int j = n->index(c);
  c->info().facet_patch[i] = 0;
  n->info().facet_patch[j] = 0;
  if (c->info().label == n->info().label) return;

  Point3 a, b;
  if (!dual_segment(c, i, a, b)) return;
  const std::optional<SurfaceHit> hit = oracle_.intersect(a, b);
  if (!hit) return;
  c->info().facet_patch[i] = hit->patch.value;
  c->info().surface_center[i] = hit->point;
  n->info().facet_patch[j] = hit->patch.value;
  n->info().surface_center[j] = hit->point;

  const double badness = facet_badness(c, i);
  if (badness > 0) facet_queue_.push({badness, c->info().stamp, c, i});
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
  const double r2 = squared_norm(p[0] - center);
  const double sigma = criteria_.facet_size(center);
  if (r2 > sigma * sigma) badness = std::max(badness, r2 / (sigma * sigma));
  // R4.2: shape, as a minimum angle: min edge^2 >= 4 sin^2(angle) R_triangle^2.
  const Point3 tc = triangle_circumcenter(p[0], p[1], p[2]);
  const double tri_r2 = squared_norm(p[0] - tc);
  const double e2 = min_squared_edge(p[0], p[1], p[2]);
  if (!(e2 >= facet_shape_bound_ * tri_r2)) {
    badness = std::max(badness, e2 > 0 ? facet_shape_bound_ * tri_r2 / e2 : 1e200);
  }
  // Approximation: the facet's circumcenter is close to its ball center on the patch.
  const double d2 = squared_norm(tc - center);
  const double dmax2 = criteria_.facet_distance * criteria_.facet_distance;
  if (!(d2 <= dmax2)) badness = std::max(badness, std::isfinite(d2) ? d2 / dmax2 : 1e200);
  return badness;
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
  const double e2 = min_squared_edge(
      to_point3(c->vertex(0)->point()), to_point3(c->vertex(1)->point()),
      to_point3(c->vertex(2)->point()), to_point3(c->vertex(3)->point()));
  const double limit = cell_shape_bound_sq_ * e2;
  if (info.squared_radius > limit) badness = std::max(badness, info.squared_radius / limit);
  return badness;
}

}  // namespace rdmesh::detail
