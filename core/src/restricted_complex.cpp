// The restricted complex of RR-7912 section 3, maintained cell by cell:
//  - D|O: a cell belongs to the mesh when its circumcenter lies in a subdomain
//    (its label, from the oracle's locate());
//  - D|S_k: a facet belongs to D|S_k when its dual Voronoi edge crosses patch
//    S_k. The edge joins the circumcenters of the two incident cells, so it
//    crosses the boundary when their labels differ; the crossing point, found
//    by the oracle, is the center of the facet's surface Delaunay ball.
#include "restricted_complex.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "simplex_geometry.h"

namespace rdmesh::detail {

namespace {
/// The clip box is the oracle's box grown by this fraction of its diagonal.
constexpr double kClipMargin = 0.05;
}  // namespace

RestrictedComplex::RestrictedComplex(const DomainOracle& oracle, bool surface_only)
    : oracle_(oracle), surface_only_(surface_only) {
  const Box3 box = oracle_.bounding_box();
  const double margin = kClipMargin * box.diagonal();
  clip_box_ = {box.lo - Point3{margin, margin, margin}, box.hi + Point3{margin, margin, margin}};
}

void RestrictedComplex::set_feature_patches(std::vector<std::vector<PatchId>> corner_patches,
                                            std::vector<std::vector<PatchId>> curve_patches) {
  corner_patches_ = std::move(corner_patches);
  curve_patches_ = std::move(curve_patches);
}

void RestrictedComplex::stamp_new(CellInfo& c) {
  c.stamp = next_stamp_++;
  if ((c.stamp >> 6) >= live_.size()) live_.resize(2 * live_.size() + 1024, 0);
  live_[c.stamp >> 6] |= std::uint64_t{1} << (c.stamp & 63);
}

void RestrictedComplex::kill(CellInfo& c) {
  live_[c.stamp >> 6] &= ~(std::uint64_t{1} << (c.stamp & 63));
  c.stamp = 0;
}

void RestrictedComplex::reserve_stamp_blocks(std::uint32_t each, std::vector<StampBlock>& blocks) {
  // Each block starts on a fresh word of live bits: a lane's plain reads of
  // its own new bits never meet another lane's writes in the same word.
  for (StampBlock& b : blocks) {
    next_stamp_ = (next_stamp_ + 63u) & ~63u;
    b.next = next_stamp_;
    b.end = next_stamp_ + each;
    next_stamp_ = b.end;
  }
  if ((next_stamp_ >> 6) >= live_.size()) live_.resize((next_stamp_ >> 6) + 1024, 0);
}

void RestrictedComplex::init_cell_in_lane(Cell_handle c, Cell_handle from, StampBlock& block) {
  CellInfo& info = c->info();
  info.stamp = block.next++;
  std::atomic_ref<std::uint64_t>(live_[info.stamp >> 6])
      .fetch_or(std::uint64_t{1} << (info.stamp & 63), std::memory_order_relaxed);
  label_cell(c, from);
}

void RestrictedComplex::kill_in_lane(CellInfo& c) {
  std::atomic_ref<std::uint64_t>(live_[c.stamp >> 6])
      .fetch_and(~(std::uint64_t{1} << (c.stamp & 63)), std::memory_order_relaxed);
  c.stamp = 0;
}

void RestrictedComplex::init_cell(Cell_handle c, Cell_handle from) {
  stamp_new(c->info());
  label_cell(c, from);
}

void RestrictedComplex::label_cell(Cell_handle c, Cell_handle from) {
  CellInfo& info = c->info();
  info.facet_patch.fill(kNotRestricted);
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
  if (!finite_center || surface_only_) {
    info.label = kOutside.value;
    return;
  }
  const bool known = from != Cell_handle() && from->info().stamp != 0 && !tr_.is_infinite(from) &&
                     is_finite(from->info().circumcenter);
  if (!known) {
    info.label = oracle_.locate(info.circumcenter).label.value;
    return;
  }
  // [circumcenter, from's] is the dual edge of the facet between the two
  // cells: a crossing found on it serves that facet too (update_facet()).
  const Located l = oracle_.locate(
      info.circumcenter, LocateHint{from->info().circumcenter, SubdomainId{from->info().label}});
  info.label = l.label.value;
  if (l.crossing && l.label.value != from->info().label) {
    const int i = c->index(from);
    info.crossing_facet = static_cast<std::int8_t>(i);
    info.crossing_with = from->info().stamp;
    info.facet_patch[i] = l.crossing->patch;
    info.surface_center.set(i, l.crossing->point);
  }
}

void RestrictedComplex::init_unstamped_cells() {
  std::vector<std::pair<Cell_handle, Cell_handle>> sweep;  // (cell, labeled neighbor)
  for (auto c = tr_.all_cells_begin(); c != tr_.all_cells_end(); ++c) {
    if (c->info().stamp != 0) continue;
    sweep.emplace_back(c, Cell_handle());
    while (!sweep.empty()) {
      const auto [d, from] = sweep.back();
      sweep.pop_back();
      if (d->info().stamp != 0) continue;
      init_cell(d, from);
      for (int i = 0; i < 4; ++i) {
        if (d->neighbor(i)->info().stamp == 0) sweep.emplace_back(d->neighbor(i), d);
      }
    }
  }
}

std::optional<SurfaceHit> RestrictedComplex::take_crossing(Cell_handle c, int i, Cell_handle n) {
  CellInfo& info = c->info();
  if (info.crossing_facet != i) return std::nullopt;
  info.crossing_facet = -1;
  if (info.crossing_with != n->info().stamp || info.facet_patch[i] == kNotRestricted)
    return std::nullopt;
  return SurfaceHit{info.surface_center[i], info.facet_patch[i]};
}

bool RestrictedComplex::dual_segment(Cell_handle c, int i, Point3& a, Point3& b) const {
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

bool RestrictedComplex::update_facet(Cell_handle c, int i) {
  const Cell_handle n = c->neighbor(i);
  const int j = n->index(c);
  std::optional<SurfaceHit> hit = take_crossing(c, i, n);
  if (!hit) hit = take_crossing(n, j, c);
  c->info().facet_patch[i] = kNotRestricted;
  n->info().facet_patch[j] = kNotRestricted;
  // Equal labels: no crossing (or an even number, which refinement removes).
  // Surface only, every dual edge is asked: an open patch has no sides.
  if (c->info().label == n->info().label && !surface_only_) return false;

  if (!hit) {
    Point3 a, b;
    if (!dual_segment(c, i, a, b)) return false;
    hit = oracle_.intersect(a, b);
    if (!hit) return false;
  }
  c->info().facet_patch[i] = hit->patch;
  c->info().surface_center.set(i, hit->point);
  n->info().facet_patch[j] = hit->patch;
  n->info().surface_center.set(j, hit->point);
  return true;
}

double RestrictedComplex::facet_power(Cell_handle c, int i, const Point3& x) const {
  const Weighted_point& q = c->vertex((i + 1) & 3)->point();
  return squared_norm(x - to_point3(q)) - q.weight();
}

bool RestrictedComplex::on_patch(const VertexInfo& v, PatchId patch) const {
  auto contains = [patch](const std::vector<PatchId>& patches) {
    return std::find(patches.begin(), patches.end(), patch) != patches.end();
  };
  switch (v.dim()) {
    case FeatureDim::kPatch:
      return v.feature.patch() == patch;
    case FeatureDim::kCurve:
      return contains(curve_patches_[v.feature.curve().value - 1]);
    case FeatureDim::kCorner:
      return contains(corner_patches_[v.feature.corner().value - 1]);
    case FeatureDim::kVolume:
      return false;
  }
  return false;
}

}  // namespace rdmesh::detail
