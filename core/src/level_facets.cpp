// The facet level: rules R3 and R4 on the facets of D|S (RR-7912 section 3).
#include "level_facets.h"

#include <cmath>

#include "level_curves.h"
#include "rdmesh/debug_assert.h"
#include "simplex_geometry.h"

namespace rdmesh::detail {

FacetLevel::FacetLevel(const RestrictedComplex& complex, const Criteria& criteria)
    : complex_(complex), criteria_(criteria) {
  const double s = std::sin(criteria_.facet_angle_deg * M_PI / 180.0);
  shape_bound_ = 4.0 * s * s;
}

Violation FacetLevel::violation(Cell_handle c, int i) const {
  const PatchId patch = c->info().facet_patch[i];
  if (patch == kNotRestricted) return {};
  RDMESH_DEBUG_ASSERT(c->neighbor(i)->info().facet_patch[c->neighbor(i)->index(c)] == patch,
                      "both cells of a restricted facet name its patch");
  const Vertex_handle v[3] = {c->vertex((i + 1) & 3), c->vertex((i + 2) & 3),
                              c->vertex((i + 3) & 3)};
  // R3: every vertex of a facet of D|S_k must lie on S_k (or on its boundary curves).
  for (const Vertex_handle& vh : v) {
    if (!complex_.on_patch(vh->info(), patch)) return Violation::topological(Rule::kR3NotFaithful);
  }
  const Point3 p[3] = {to_point3(v[0]->point()), to_point3(v[1]->point()),
                       to_point3(v[2]->point())};
  const Point3 center = c->info().surface_center[i];
  Violation worst;
  // R4.1: surface Delaunay ball radius against the sizing field.
  const double r2 = complex_.facet_power(c, i, center);
  const double sigma = criteria_.facet_size(center);
  if (r2 > sigma * sigma) worst.worsen(Rule::kR4Size, r2 / (sigma * sigma));
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
  if (!(e2 >= shape_bound_ * shape_r2)) {
    worst.worsen(Rule::kR4Shape, e2 > 0 ? shape_bound_ * shape_r2 / e2 : kDegenerateRatio);
  }
  // Approximation: the ball center on the patch is close to the facet's plane
  // (its distance to the facet's orthocenter, the foot of the dual edge; the
  // circumcenter when no vertex is weighted).
  const Point3 oc = weighted ? triangle_orthocenter(p[0], w[0], p[1], w[1], p[2], w[2]) : tc;
  const double d2 = squared_norm(oc - center);
  const double dmax = criteria_.facet_distance(center), dmax2 = dmax * dmax;
  if (!(d2 <= dmax2)) {
    worst.worsen(Rule::kR4Distance, std::isfinite(d2) ? d2 / dmax2 : kDegenerateRatio);
  }
  return worst;
}

void FacetLevel::consider(Cell_handle c, int i) {
  const Violation v = violation(c, i);
  if (!v) return;
  const ElementEntry e{v.priority, c, c->info().stamp, i};
  const int lane = lane_of(c, i);
  if (lane >= 0) return lanes_[lane].push(e);
  queue_.push(e);
}

int FacetLevel::lane_of(Cell_handle c, int i) const { return fits_lane(c, i) ? owner(c, i) : -1; }

bool FacetLevel::fits_lane(Cell_handle c, int i) const {
  if (!lanes_on_) return false;
  const Point3 center = c->info().surface_center[i];
  return complex_.facet_power(c, i, center) < lane_max_squared_radius_;
}

int FacetLevel::owner(Cell_handle c, int i) const {
  const Cell_handle n = c->neighbor(i);
  for (int lane = 0; lane < 2; ++lane) {
    if (cut_->in_lane(c, lane) && cut_->in_lane(n, lane)) return lane;
  }
  return -1;
}

std::optional<ElementEntry> FacetLevel::pop() {
  ElementEntry e = queue_.top();
  queue_.pop();
  const bool pinned = e.facet >= kPinned;
  e.facet &= 3;
  if (!complex_.is_live(e.stamp) || !violation(e.cell, e.facet)) return std::nullopt;
  if (!pinned && fits_lane(e.cell, e.facet)) {
    const int lane = owner(e.cell, e.facet);
    if (lane >= 0)
      lanes_[lane].push(e);
    else
      parked_.push_back(e);
    return std::nullopt;
  }
  return e;
}

bool FacetLevel::refine(Cell_handle c, int i, Insertion& insertion, CurveLevel& curves) {
  const Point3 center = c->info().surface_center[i];
  const Weighted_point p = to_weighted(center);
  // The ball center lies on the dual Voronoi edge, hence inside the Delaunay
  // ball of at least one of the two incident cells.
  Cell_handle start = c;
  const Triangulation& tr = complex_.triangulation();
  if (tr.side_of_power_sphere(start, p) != CGAL::ON_BOUNDED_SIDE) start = c->neighbor(i);
  const VertexInfo info{FeatureRef(c->info().facet_patch[i]), 0, -1};
  if (curves.keeps_facet_centre(c, i, info, insertion)) return false;
  if (!insertion.find_zone(p, start)) {
    insertion.record_guard(info, c->vertex((i + 1) & 3)->info());  // the center is a vertex
    return false;
  }
  if (const std::optional<bool> inserted = curves.refine_encroached(center, insertion)) {
    ++insertion.stats().encroachments;
    return *inserted;
  }
  if (insertion.insert(p, info) == Vertex_handle()) return false;
  ++insertion.stats().inserted_facet_centers;
  return true;
}

bool FacetLevel::encroached(const Point3& x, const std::vector<Cell_handle>& zone,
                            Cell_handle& cell, int& facet) const {
  double best = -1;
  for (const Cell_handle& z : zone) {
    for (int i = 0; i < 4; ++i) {
      if (z->info().facet_patch[i] == kNotRestricted) continue;
      const Point3 sc = z->info().surface_center[i];
      const double r2 = complex_.facet_power(z, i, sc);
      if (squared_norm(x - sc) < r2 && r2 > best) {
        cell = z;
        facet = i;
        best = r2;
      }
    }
  }
  return best >= 0;
}

}  // namespace rdmesh::detail
