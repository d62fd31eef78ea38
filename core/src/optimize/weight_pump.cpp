// Weight pumping of one vertex: candidate zones in order of critical weight,
// their validity against the restricted complex, the exact re-check and the
// in-place re-triangulation (see weight_pump.h for the rules).
#include "weight_pump.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "../simplex_geometry.h"
#include "cell_shape.h"
#include "cone_hole.h"
#include "rdmesh/errors.h"
#include "tet_shape.h"

namespace rdmesh::detail {
namespace {

/// facet_cosine_'s mark of a cosine not computed yet (cosines are <= 1).
constexpr double kUnknownCosine = 2.0;

/// Weight of v at which it enters the power sphere of finite cell c (v is not
/// a vertex of c): |v - z|^2 - r^2 for c's orthosphere (z, r^2), computed
/// relative to c's first vertex. Infinite for a flat cell.
double critical_weight(Cell_handle c, const Point3& v) {
  const Weighted_point& q0 = c->vertex(0)->point();
  const Point3 p0 = to_point3(q0);
  Point3 u[3];
  double b[3];
  for (int i = 0; i < 3; ++i) {
    const Weighted_point& q = c->vertex(i + 1)->point();
    u[i] = to_point3(q) - p0;
    b[i] = 0.5 * (squared_norm(u[i]) - q.weight() + q0.weight());
  }
  const double det = dot(u[0], cross(u[1], u[2]));
  if (!(std::abs(det) > 0)) return std::numeric_limits<double>::infinity();
  // Orthocenter z = p0 + x with u_i . x = b_i.
  const Point3 x = (1.0 / det) *
                   (b[0] * cross(u[1], u[2]) + b[1] * cross(u[2], u[0]) + b[2] * cross(u[0], u[1]));
  const Point3 d = v - p0;
  const double crit = squared_norm(d) + q0.weight() - 2.0 * dot(d, x);
  return std::isfinite(crit) ? crit : std::numeric_limits<double>::infinity();
}

}  // namespace

WeightPump::WeightPump(Triangulation& tr, std::uint32_t first_stamp, CellLimits limits,
                       const ChainEdges* chains)
    : tr_(tr), next_stamp_(first_stamp), limits_(limits), chains_(chains) {
  zone_.reserve(128);
  boundary_.reserve(256);
}

bool WeightPump::collect_star(Vertex_handle v, const std::vector<Cell_handle>* star,
                              double star_cosine) {
  zone_.clear();
  star_facets_.clear();
  if (star != nullptr) {
    zone_.assign(star->begin(), star->end());
    zone_quality_ = star_cosine;
  } else {
    if (!walk_.cells_if(v, zone_, [&](Cell_handle c) { return in_lane(c); })) {
      zone_.clear();
      return false;
    }
    zone_quality_ = -std::numeric_limits<double>::infinity();
    for (const Cell_handle& c : zone_)
      zone_quality_ = std::max(zone_quality_, c->info().shape_cosine);
  }
  star_size_ = zone_.size();
  for (const Cell_handle& c : zone_) c->tds_data().mark_in_conflict();
  // The restricted facets (v, a, b) of the star, each once (from the cell of
  // smaller stamp; both cells hold the same data).
  for (const Cell_handle& c : zone_) {
    const int iv = c->index(v);
    for (int i = 0; i < 4; ++i) {
      if (i == iv || c->info().facet_patch[i] == kNotRestricted) continue;
      const Cell_handle n = c->neighbor(i);
      if (n->info().stamp < c->info().stamp) continue;
      StarFacet f;
      for (int k = 1; k < 4; ++k) {
        const Vertex_handle u = c->vertex((i + k) & 3);
        if (u == v) continue;
        (f.a == Vertex_handle() ? f.a : f.b) = u;
      }
      if (vertex_less(f.b, f.a)) std::swap(f.a, f.b);
      f.patch = c->info().facet_patch[i];
      f.center = c->info().surface_center[i];
      f.label0 = c->info().label;
      f.label1 = n->info().label;
      star_facets_.push_back(f);
    }
  }
  return true;
}

void WeightPump::push_frontier(Cell_handle c, Vertex_handle v) {
  // A cell next to Z shares three vertices with a cell of the lane: the other
  // lane never owns it, so nobody writes its mark while this pump reads it.
  if (c->tds_data().is_in_conflict()) return;
  if (!in_lane(c)) {
    left_lane_ = true;
    return;
  }
  if (tr_.is_infinite(c)) return;
  frontier_.push({critical_weight(c, to_point3(v->point())), c});
}

bool WeightPump::absorb(Cell_handle c) {
  if (tr_.is_infinite(c)) return false;
  for (int i = 0; i < 4; ++i) {
    // A restricted facet between c and Z would be inside the new zone.
    if (c->info().facet_patch[i] != kNotRestricted && c->neighbor(i)->tds_data().is_in_conflict())
      return false;
  }
  c->tds_data().mark_in_conflict();
  zone_.push_back(c);
  zone_quality_ = std::max(zone_quality_, c->info().shape_cosine);
  return true;
}

bool WeightPump::within_limits(const Point3& v, const Point3& a, const Point3& b,
                               const Point3& c) const {
  if (limits_.criteria == nullptr || !(limits_.size || limits_.radius_edge)) return true;
  const Point3 center = tet_circumcenter(v, a, b, c);
  const double r2 = squared_norm(center - v);
  if (!std::isfinite(r2)) return false;
  if (limits_.size) {
    const double sigma = limits_.criteria->cell_size(center);
    if (r2 > sigma * sigma) return false;
  }
  if (limits_.radius_edge) {
    const double beta = limits_.criteria->cell_radius_edge;
    if (r2 > beta * beta * min_squared_edge(v, a, b, c)) return false;
  }
  return true;
}

void WeightPump::clear_marks() {
  for (const Cell_handle& c : zone_) c->tds_data().clear();
}

double WeightPump::boundary_quality(Vertex_handle v, double cutoff, bool measure) {
  boundary_.clear();
  const Point3 pv = to_point3(v->point());
  double quality = -std::numeric_limits<double>::infinity();
  if (measure) facet_cosine_.resize(4 * zone_.size(), kUnknownCosine);
  for (std::size_t z = 0; z < zone_.size(); ++z) {
    const Cell_handle c = zone_[z];
    for (int i = 0; i < 4; ++i) {
      const Cell_handle n = c->neighbor(i);
      if (n->tds_data().is_in_conflict()) continue;
      BoundaryFacet f{c, i, 0, false, static_cast<std::uint32_t>(z)};
      f.label = c->info().facet_patch[i] != kNotRestricted ? c->info().label : n->info().label;
      for (int k = 1; k < 4; ++k)
        f.infinite = f.infinite || tr_.is_infinite(c->vertex((i + k) & 3));
      boundary_.push_back(f);
      if (!measure || f.infinite || f.label == 0) continue;
      // The new cell v + facet does not depend on the weight: one cosine per pump.
      double& cosine = facet_cosine_[4 * z + static_cast<std::size_t>(i)];
      if (cosine == kUnknownCosine)
        cosine = max_dihedral_cosine(pv, to_point3(c->vertex((i + 1) & 3)->point()),
                                     to_point3(c->vertex((i + 2) & 3)->point()),
                                     to_point3(c->vertex((i + 3) & 3)->point()));
      quality = std::max(quality, cosine);
      if (!(quality < cutoff)) {
        rejecting_ = {c, i, cosine};
        return quality;
      }
    }
  }
  return quality;
}

WeightPump::Check WeightPump::validate(Vertex_handle v) {
  edges_.reset(3 * boundary_.size());
  if (++mark_ == 0) {  // wrapped: reset the marks
    std::fill(vertex_mark_.begin(), vertex_mark_.end(), 0);
    mark_ = 1;
  }
  const Weighted_point& vp = v->point();
  auto mark = [&](Vertex_handle u) -> std::uint32_t& {
    const int id = u->info().index;
    if (id < 0) return infinite_mark_;
    if (static_cast<std::size_t>(id) >= vertex_mark_.size()) vertex_mark_.resize(id + 1, 0);
    return vertex_mark_[static_cast<std::size_t>(id)];
  };
  for (std::size_t b = 0; b < boundary_.size(); ++b) {
    const BoundaryFacet& f = boundary_[b];
    const Cell_handle c = f.inner;
    const int i = f.index;
    const Vertex_handle w[3] = {c->vertex((i + 1) & 3), c->vertex((i + 2) & 3),
                                c->vertex((i + 3) & 3)};
    if (!f.infinite) {
      // The new cell is c with vertex i replaced by v: it must be positive.
      const Weighted_point* q[4];
      for (int k = 0; k < 4; ++k) q[k] = k == i ? &vp : &c->vertex(k)->point();
      if (CGAL::orientation(q[0]->point(), q[1]->point(), q[2]->point(), q[3]->point()) !=
          CGAL::POSITIVE)
        return Check::kInvalid;
      if (f.label != 0 && !within_limits(to_point3(vp), to_point3(w[0]->point()),
                                         to_point3(w[1]->point()), to_point3(w[2]->point())))
        return Check::kInvalid;
    }
    for (int k = 0; k < 3; ++k) {
      mark(w[k]) = mark_;
      edges_.add(w[k], w[(k + 1) % 3], static_cast<int>(b));
    }
  }
  // No vertex of Z may end up inside it (it would be hidden); no feature edge may be lost.
  for (std::size_t z = 0; z < zone_.size(); ++z) {
    const Cell_handle c = zone_[z];
    for (int k = 0; k < 4; ++k) {
      const Vertex_handle u = c->vertex(k);
      if (u == v) continue;
      if (mark(u) != mark_) return Check::kInvalidFromNowOn;
      if (z < star_size_ || tr_.is_infinite(u) || u->info().dim() > FeatureDim::kCurve) continue;
      for (int l = k + 1; l < 4; ++l) {
        const Vertex_handle t = c->vertex(l);
        if (tr_.is_infinite(t) || t->info().dim() > FeatureDim::kCurve) continue;
        if (chains_ != nullptr && !chains_->contains(u, t)) continue;
        if (!edges_.contains(u, t)) return Check::kInvalidFromNowOn;
      }
    }
  }
  // Every restricted facet of the old star must stay a facet.
  for (const StarFacet& f : star_facets_)
    if (!edges_.contains(f.a, f.b)) return Check::kInvalidFromNowOn;
  // Each boundary edge ab is held by two boundary facets: the new cells on
  // either side of the new facet (v, a, b). Their labels must agree with the
  // restricted facets of the old star.
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const EdgeTable::Edge& e = edges_[k];
    if (e.count != 2) return Check::kInvalid;  // not a closed 2-manifold surface
    const int lx = boundary_[e.facet[0]].label, ly = boundary_[e.facet[1]].label;
    const StarFacet* restricted = nullptr;
    for (const StarFacet& f : star_facets_)
      if (f.a == e.a && f.b == e.b) restricted = &f;
    if (restricted == nullptr) {
      if (lx != ly) return Check::kInvalid;
    } else if (!((lx == restricted->label0 && ly == restricted->label1) ||
                 (lx == restricted->label1 && ly == restricted->label0))) {
      return Check::kInvalid;
    }
  }
  return Check::kValid;
}

WeightPump::Outcome WeightPump::pump(Vertex_handle v, double max_weight,
                                     const std::vector<Cell_handle>* star, double star_cosine) {
  if (!collect_star(v, star, star_cosine)) return Outcome::kDeferred;
  left_lane_ = false;
  frontier_.clear();
  rejecting_ = {};
  facet_cosine_.clear();
  for (std::size_t z = 0; z < star_size_; ++z)
    __builtin_prefetch(&*zone_[z]->neighbor(zone_[z]->index(v)));
  for (std::size_t z = 0; z < star_size_; ++z) {
    const Cell_handle n = zone_[z]->neighbor(zone_[z]->index(v));
    const Cell_handle c = zone_[z];
    __builtin_prefetch(&*n->vertex(n->index(c)));
  }
  for (std::size_t z = 0; z < star_size_; ++z)
    push_frontier(zone_[z]->neighbor(zone_[z]->index(v)), v);
  if (left_lane_) {
    clear_marks();
    return Outcome::kDeferred;
  }

  double best_weight = -1, best_quality = 0;
  std::size_t best_size = 0;
  while (!frontier_.empty()) {
    const double crit = frontier_.top().crit;
    if (!(crit < max_weight)) break;
    // Every cell whose critical weight is <= crit joins Z (ties, and cells in
    // conflict already because their weight is below the current level).
    bool stop = false;
    while (!frontier_.empty() && frontier_.top().crit <= crit) {
      const Cell_handle c = frontier_.top().cell;
      frontier_.pop();
      if (c->tds_data().is_in_conflict()) continue;
      if (!absorb(c)) {
        stop = true;
        break;
      }
      for (int i = 0; i < 4; ++i) __builtin_prefetch(&*c->neighbor(i));
      for (int i = 0; i < 4; ++i) push_frontier(c->neighbor(i), v);
      if (left_lane_) {
        clear_marks();
        return Outcome::kDeferred;
      }
    }
    if (stop) break;
    const double next = frontier_.empty() ? max_weight : std::min(frontier_.top().crit, max_weight);
    const double weight = 0.5 * (crit + next);
    if (!(weight > crit && weight > v->point().weight())) continue;
    // Cheap first: only a candidate better than the best so far is validated.
    const double cutoff = best_weight < 0 ? zone_quality_ : std::min(zone_quality_, best_quality);
    // The new cell that rejected the last candidate, if its facet is still on
    // the boundary of Z, rejects this one too (Z only grows during a pump).
    if (rejecting_.inner != Cell_handle() && !(rejecting_.cosine < cutoff) &&
        !rejecting_.inner->neighbor(rejecting_.index)->tds_data().is_in_conflict())
      continue;
    const double quality = boundary_quality(v, cutoff);
    if (!(quality < cutoff)) continue;
    const Check check = validate(v);
    if (check == Check::kInvalidFromNowOn) break;
    if (check != Check::kValid) continue;
    best_weight = weight;
    best_quality = quality;
    best_size = zone_.size();
  }
  clear_marks();
  if (best_weight < 0) return Outcome::kNoImprovement;
  zone_.resize(best_size);
  return commit(v, best_weight);
}

WeightPump::Outcome WeightPump::commit(Vertex_handle v, double weight) {
  const Weighted_point wp(v->point().point(), weight);
  // Z is the zone pump() validated (the same cells in the same order, the
  // triangulation unchanged since): its new star is valid, only its boundary
  // must be listed again.
  for (const Cell_handle& c : zone_) c->tds_data().mark_in_conflict();
  boundary_quality(v, 0, /*measure=*/false);
  // The exact conflict zone of (v, weight), found from v's cell, must be Z:
  // every cell of Z in conflict, none of the cells next to it.
  bool exact = true;
  for (std::size_t z = 0; exact && z < zone_.size(); ++z)
    exact = tr_.side_of_power_sphere(zone_[z], wp, true) == CGAL::ON_BOUNDED_SIDE;
  for (std::size_t b = 0; exact && b < boundary_.size(); ++b)
    exact = tr_.side_of_power_sphere(boundary_[b].inner->neighbor(boundary_[b].index), wp, true) !=
            CGAL::ON_BOUNDED_SIDE;
  const std::size_t more = boundary_.size() > zone_.size() ? boundary_.size() - zone_.size() : 0;
  if (!exact || (pool_ != nullptr && pool_->size() < more)) {
    clear_marks();
    return exact ? Outcome::kDeferred : Outcome::kInexact;
  }
  // What each new cell keeps of the boundary facet it stands on (read now: the
  // cone overwrites the cells of Z).
  struct Kept {
    int label;
    double cosine;  ///< the new cell's shape_cosine
    PatchId patch;  ///< of the boundary facet (both its sides hold the same data)
    Point3 center;
  };
  std::vector<Kept> kept;
  kept.reserve(boundary_.size());
  hole_facets_.clear();
  const Point3 pv = to_point3(v->point());
  for (const BoundaryFacet& f : boundary_) {
    double cosine = -std::numeric_limits<double>::infinity();
    if (!f.infinite && f.label != 0) {
      // Measured when pump() rated this zone (it rated it in full), else now.
      const std::size_t k = 4 * f.zone_index + static_cast<std::size_t>(f.index);
      cosine = k < facet_cosine_.size() ? facet_cosine_[k] : kUnknownCosine;
      if (cosine == kUnknownCosine)
        cosine = max_dihedral_cosine(pv, to_point3(f.inner->vertex((f.index + 1) & 3)->point()),
                                     to_point3(f.inner->vertex((f.index + 2) & 3)->point()),
                                     to_point3(f.inner->vertex((f.index + 3) & 3)->point()));
    }
    const PatchId patch = f.inner->info().facet_patch[f.index];
    kept.push_back({f.label, cosine, patch,
                    patch != kNotRestricted ? f.inner->info().surface_center[f.index] : Point3{}});
    hole_facets_.push_back({f.inner, f.index});
  }
  // Re-triangulate the hole as the cone from v (the same vertex object).
  cone_.build(tr_, zone_, hole_facets_, v, pool_, new_cells_);
  v->set_point(wp);

  for (std::size_t n = 0; n < new_cells_.size(); ++n) {
    const Cell_handle c = new_cells_[n];
    const Kept& o = kept[n];
    CellInfo& info = c->info();
    info.stamp = next_stamp_;
    next_stamp_ += stamp_stride_;
    info.label = o.label;
    info.facet_patch.fill(kNotRestricted);
    const int k = hole_facets_[n].index;  // v's index in c
    info.facet_patch[k] = o.patch;
    if (o.patch != kNotRestricted) info.surface_center.set(k, o.center);
    for (int i = 0; i < 4; ++i) {
      if (i == k) continue;
      Vertex_handle a, b;
      for (int j = 1; j < 4; ++j) {
        const Vertex_handle u = c->vertex((i + j) & 3);
        if (u != v) (a == Vertex_handle() ? a : b) = u;
      }
      if (vertex_less(b, a)) std::swap(a, b);
      for (const StarFacet& f : star_facets_) {
        if (f.a == a && f.b == b) {
          info.facet_patch[i] = f.patch;
          info.surface_center.set(i, f.center);
        }
      }
    }
    if (tr_.is_infinite(c)) info.label = 0;
    info.shape_cosine = o.cosine;
  }
  return Outcome::kAccepted;
}

}  // namespace rdmesh::detail
