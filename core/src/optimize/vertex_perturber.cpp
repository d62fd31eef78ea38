// Sliver perturbation of volume vertices (see vertex_perturber.h).
#include "vertex_perturber.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "../simplex_geometry.h"
#include "cell_shape.h"
#include "rdmesh/errors.h"
#include "tet_shape.h"

namespace rdmesh::detail {
namespace {

Weighted_point weighted(const Point3& p, double w) {
  return Weighted_point(Kernel::Point_3(p.x, p.y, p.z), w);
}

bool has_restricted_facet(Cell_handle c) {
  const auto& p = c->info().facet_patch;
  return p[0] != kNotRestricted || p[1] != kNotRestricted || p[2] != kNotRestricted ||
         p[3] != kNotRestricted;
}

}  // namespace

VertexPerturber::VertexPerturber(Triangulation& tr, std::uint32_t first_stamp)
    : tr_(tr), next_stamp_(first_stamp) {}

Point3 VertexPerturber::angle_gradient(Cell_handle c, Vertex_handle v, double h) const {
  Point3 q[3];
  int n = 0;
  for (int k = 0; k < 4; ++k)
    if (c->vertex(k) != v) q[n++] = to_point3(c->vertex(k)->point());
  const Point3 p = to_point3(v->point());
  auto angle = [&](const Point3& x) { return std::acos(max_dihedral_cosine(x, q[0], q[1], q[2])); };
  const Point3 axes[3] = {{h, 0, 0}, {0, h, 0}, {0, 0, h}};
  double g[3];
  for (int a = 0; a < 3; ++a) g[a] = (angle(p + axes[a]) - angle(p - axes[a])) / (2 * h);
  return {g[0], g[1], g[2]};
}

bool VertexPerturber::movable_to(Vertex_handle v, const Point3& p, int label, double nearest,
                                 double& worst) {
  const Weighted_point wp = weighted(p, v->point().weight());
  Triangulation::Locate_type lt;
  int li = 0, lj = 0;
  const Cell_handle c = tr_.locate(wp, lt, li, lj, v->cell());
  // p must lie in the star of v (keeps the changed region one connected piece).
  if (lt == Triangulation::VERTEX || tr_.is_infinite(c) || !c->has_vertex(v)) return false;
  conflicts_.clear();
  facets_.clear();
  tr_.find_conflicts(wp, c, std::back_inserter(facets_), std::back_inserter(conflicts_));
  if (conflicts_.empty()) return false;
  worst = -std::numeric_limits<double>::infinity();
  const double min_d2 = 0.25 * nearest * nearest;
  for (const std::vector<Cell_handle>* cells : {&star_, &conflicts_}) {
    for (const Cell_handle& z : *cells) {
      if (tr_.is_infinite(z) || z->info().label != label || has_restricted_facet(z)) return false;
      for (int k = 0; k < 4; ++k) {
        const Vertex_handle u = z->vertex(k);
        if (u != v && squared_norm(to_point3(u->point()) - p) < min_d2) return false;
      }
      worst = std::max(worst, cell_cosine(z));
    }
  }
  // No vertex may get hidden: each vertex of a destroyed cell keeps a cell
  // that is neither incident to v nor in conflict with p.
  for (const Cell_handle& z : conflicts_) z->tds_data().mark_in_conflict();
  bool hidden = false;
  for (const Cell_handle& z : conflicts_) {
    for (int k = 0; k < 4 && !hidden; ++k) {
      const Vertex_handle u = z->vertex(k);
      if (u == v) continue;
      incident_.clear();
      tr_.incident_cells(u, std::back_inserter(incident_));
      hidden = std::none_of(incident_.begin(), incident_.end(), [&](const Cell_handle& x) {
        return !x->has_vertex(v) && !x->tds_data().is_in_conflict();
      });
    }
  }
  for (const Cell_handle& z : conflicts_) z->tds_data().clear();
  return !hidden;
}

double VertexPerturber::move(Vertex_handle v, const Point3& p, int label) {
  const std::uint32_t first_new = next_stamp_;
  const std::size_t vertices = tr_.number_of_vertices();
  if (tr_.move_if_no_collision(v, weighted(p, v->point().weight())) != v ||
      tr_.number_of_vertices() != vertices)
    throw InternalError(
        "perturbation: a vertex collided although it was kept away from all others");
  // New cells have the default stamp 0: collect them from the new star.
  new_cells_.clear();
  tr_.incident_cells(v, std::back_inserter(new_cells_));
  for (const Cell_handle& c : new_cells_) c->info().stamp = next_stamp_++;
  double worst = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < new_cells_.size(); ++k) {
    const Cell_handle c = new_cells_[k];
    for (int i = 0; i < 4; ++i) {
      const Cell_handle n = c->neighbor(i);
      if (n->info().stamp == 0) {
        n->info().stamp = next_stamp_++;
        new_cells_.push_back(n);
      } else if (n->info().stamp < first_new &&
                 (n->info().label != label ||
                  n->info().facet_patch[n->index(c)] != kNotRestricted)) {
        throw InternalError("perturbation: the re-triangulated region borders another label");
      }
    }
    CellInfo& info = c->info();
    info.label = tr_.is_infinite(c) ? 0 : label;
    info.facet_patch.fill(kNotRestricted);
    info.shape_cosine = stored_shape(tr_, c);
    worst = std::max(worst, info.shape_cosine);
  }
  return worst;
}

bool VertexPerturber::perturb(Vertex_handle v, double nearest) {
  if (v->info().dim() != FeatureDim::kVolume) return false;
  star_.clear();
  tr_.incident_cells(v, std::back_inserter(star_));
  const int label = star_.front()->info().label;
  Cell_handle worst_cell;
  double worst = -std::numeric_limits<double>::infinity();
  for (const Cell_handle& c : star_) {
    if (tr_.is_infinite(c) || c->info().label != label || label == 0 || has_restricted_facet(c))
      return false;
    const double cosine = cell_cosine(c);
    if (cosine > worst) {
      worst = cosine;
      worst_cell = c;
    }
  }
  const Point3 g = angle_gradient(worst_cell, v, 1e-4 * nearest);
  const double gn = norm(g);
  if (!(gn > 0) || !std::isfinite(gn)) return false;
  const Point3 dir = (1.0 / gn) * g;
  const Point3 origin = to_point3(v->point());
  for (const double step : {0.2, 0.1, 0.05, 0.025}) {
    const Point3 p = origin + step * nearest * dir;
    double destroyed_worst = 0;
    if (!movable_to(v, p, label, nearest, destroyed_worst)) continue;
    if (move(v, p, label) < destroyed_worst) return true;
    move(v, origin, label);  // undo: the same cells come back
    star_.clear();
    tr_.incident_cells(v, std::back_inserter(star_));
  }
  return false;
}

}  // namespace rdmesh::detail
