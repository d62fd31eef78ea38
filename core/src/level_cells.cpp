// The cell level: rule R5 on the cells of D|O (RR-7912 section 3).
#include "level_cells.h"

#include <algorithm>
#include <cmath>

#include "level_curves.h"
#include "level_facets.h"
#include "rdmesh/debug_assert.h"
#include "simplex_geometry.h"

namespace rdmesh::detail {

namespace {
/// The cell queue's buckets: four per doubling of the priority (a ratio > 1);
/// ratios above 2^64 share the last one. Narrower buckets follow the strict
/// worst-first order more closely, wider ones keep more insertions next to
/// the last (sphere, 1.1 M tets: 1 per doubling made 8% more tets, 8 per
/// doubling lost half of the speed-up).
constexpr std::size_t kBucketsPerDoubling = 4;
constexpr std::size_t kLastBucket = 256;
}  // namespace

std::size_t CellLevel::bucket_of(double priority) {
  if (!(priority > 1.0)) return 0;
  if (!std::isfinite(priority)) return kLastBucket;
  // floor(4 log2(priority)), read exactly off the binary exponent and the
  // mantissa against the doubles nearest 2^(1/4), 2^(1/2) and 2^(3/4): no
  // libm call, whose last bit may differ from one CPU to another
  // (rdmesh/portable_math.h), decides the order of refinement.
  static constexpr double kQuarterPowers[3] = {1.1892071150027210667, 1.4142135623730950488,
                                               1.6817928305074290861};
  int exponent = 0;
  const double mantissa = 2.0 * std::frexp(priority, &exponent);  // in [1, 2)
  std::size_t b = static_cast<std::size_t>(exponent - 1) * kBucketsPerDoubling;
  for (const double q : kQuarterPowers) b += mantissa >= q ? 1 : 0;
  return std::min(b, kLastBucket);
}

CellLevel::CellLevel(const RestrictedComplex& complex, const Criteria& criteria)
    : complex_(complex),
      criteria_(criteria),
      shape_bound_sq_(criteria.cell_radius_edge * criteria.cell_radius_edge) {}

Violation CellLevel::violation(Cell_handle c) const {
  const CellInfo& info = c->info();
  RDMESH_DEBUG_ASSERT(info.label == kOutside.value || !complex_.triangulation().is_infinite(c),
                      "an infinite cell is outside the domain");
  if (info.label == kOutside.value || complex_.triangulation().is_infinite(c)) return {};
  RDMESH_DEBUG_ASSERT(is_finite(info.circumcenter) && complex_.is_live(info.stamp),
                      "a cell of D|O is initialized and has a finite centre");
  Violation worst;
  // R5.1: Delaunay ball radius against the sizing field.
  const double sigma = criteria_.cell_size(info.circumcenter);
  if (info.squared_radius > sigma * sigma) {
    worst.worsen(Rule::kR5Size, info.squared_radius / (sigma * sigma));
  }
  // R5.2: radius-edge ratio <= beta_3.
  const double e2 =
      min_squared_edge(to_point3(c->vertex(0)->point()), to_point3(c->vertex(1)->point()),
                       to_point3(c->vertex(2)->point()), to_point3(c->vertex(3)->point()));
  const double limit = shape_bound_sq_ * e2;
  if (info.squared_radius > limit) worst.worsen(Rule::kR5Shape, info.squared_radius / limit);
  return worst;
}

void CellLevel::consider(Cell_handle c) {
  const Violation v = violation(c);
  if (!v) return;
  const ElementEntry e = entry(c, v);
  const int lane = fits_lane(c) ? owner(c) : -1;
  if (lane >= 0) return lanes_[lane].push(bucket_of(v.priority), e);
  queue_.push(bucket_of(v.priority), e);
}

bool CellLevel::fits_lane(Cell_handle c) const {
  return lanes_on_ && c->info().squared_radius < lane_max_squared_radius_;
}

int CellLevel::owner(Cell_handle c) const {
  for (int lane = 0; lane < 2; ++lane) {
    if (cut_->in_lane(c, lane)) return lane;
  }
  return -1;
}

std::optional<ElementEntry> CellLevel::pop() {
  ElementEntry e = queue_.pop();
  const bool pinned = e.facet == kPinned;
  e.facet = -1;
  if (!complex_.is_live(e.stamp) || !violation(e.cell)) return std::nullopt;
  if (!pinned && fits_lane(e.cell)) {
    const int lane = owner(e.cell);
    if (lane >= 0)
      lanes_[lane].push(bucket_of(e.priority), e);
    else
      parked_.push_back(e);
    return std::nullopt;
  }
  return e;
}

bool CellLevel::refine(const ElementEntry& entry, Insertion& insertion, CurveLevel& curves,
                       FacetLevel& facets) {
  const Cell_handle c = entry.cell;
  const Point3 center = c->info().circumcenter;
  if (curves.keeps_cell_centre(c)) return false;
  const Weighted_point p = to_weighted(center);
  if (!insertion.find_zone(p, c)) return false;
  bool redirected = false, inserted = false;
  if (const std::optional<bool> edge = curves.refine_encroached(center, insertion)) {
    redirected = true;
    inserted = *edge;
  } else {
    Cell_handle fc;
    int fi = -1;
    if (facets.encroached(center, insertion.zone(), fc, fi)) {
      redirected = true;
      inserted = facets.refine(fc, fi, insertion, curves);
    }
  }
  if (redirected) {
    ++insertion.stats().encroachments;
    // The cell may still need refining.
    if (inserted && complex_.is_live(entry.stamp)) queue_.push(bucket_of(entry.priority), entry);
    return inserted;
  }
  if (insertion.insert(p, VertexInfo{}) == Vertex_handle()) return false;
  ++insertion.stats().inserted_cell_centers;
  return true;
}

}  // namespace rdmesh::detail
