// Sliver perturbation of volume vertices (see vertex_perturber.h).
#include "vertex_perturber.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "../simplex_geometry.h"
#include "cell_shape.h"
#include "cone_hole.h"
#include "rdmesh/errors.h"
#include "rdmesh/portable_math.h"
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
  auto angle = [&](const Point3& x) {
    return portable_acos(max_dihedral_cosine(x, q[0], q[1], q[2]));
  };
  const Point3 axes[3] = {{h, 0, 0}, {0, h, 0}, {0, 0, h}};
  double g[3];
  for (int a = 0; a < 3; ++a) g[a] = (angle(p + axes[a]) - angle(p - axes[a])) / (2 * h);
  return {g[0], g[1], g[2]};
}

namespace {

/// Clears the conflict marks of `cells` when it goes out of scope.
struct MarkGuard {
  const std::vector<Cell_handle>& cells;
  ~MarkGuard() {
    for (const Cell_handle& c : cells) c->tds_data().clear();
  }
};

/// The weighted points of the new cell: c with vertex i replaced by `p`.
std::array<const Weighted_point*, 4> new_cell(Cell_handle c, int i, const Weighted_point& p) {
  std::array<const Weighted_point*, 4> q{};
  for (int k = 0; k < 4; ++k) q[k] = k == i ? &p : &c->vertex(k)->point();
  return q;
}

/// The vertex of boundary facet `f` that is neither a nor b.
template <class Facet>
Vertex_handle third_vertex(const Facet& f, Vertex_handle a, Vertex_handle b) {
  for (int j = 1; j < 4; ++j) {
    const Vertex_handle u = f.inner->vertex((f.index + j) & 3);
    if (u != a && u != b) return u;
  }
  return Vertex_handle();
}

/// `t` lies strictly outside the power sphere of positively oriented `q`
/// (exact). A cospherical case counts as not regular: the move is then not
/// made, so CGAL's symbolic perturbation never has to decide it here.
bool strictly_outside(const std::array<const Weighted_point*, 4>& q, const Weighted_point& t) {
  return Kernel().power_side_of_oriented_power_sphere_3_object()(*q[0], *q[1], *q[2], *q[3], t) ==
         CGAL::ON_NEGATIVE_SIDE;
}

}  // namespace

bool VertexPerturber::plan_move(Vertex_handle v, const Point3& p, int label, double nearest,
                                double& old_worst, double& new_worst) {
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
  // R: the star, then the cells in conflict that are not in it.
  region_.assign(star_.begin(), star_.end());
  const MarkGuard guard{region_};
  for (const Cell_handle& z : region_) z->tds_data().mark_in_conflict();
  for (const Cell_handle& z : conflicts_) {
    if (z->tds_data().is_in_conflict()) continue;
    z->tds_data().mark_in_conflict();
    region_.push_back(z);
  }
  old_worst = -std::numeric_limits<double>::infinity();
  const double min_d2 = 0.25 * nearest * nearest;
  for (const Cell_handle& z : region_) {
    if (tr_.is_infinite(z) || z->info().label != label || has_restricted_facet(z)) return false;
    for (int k = 0; k < 4; ++k) {
      const Vertex_handle u = z->vertex(k);
      if (u != v && squared_norm(to_point3(u->point()) - p) < min_d2) return false;
    }
    old_worst = std::max(old_worst, cell_cosine(z));
  }
  boundary_.clear();
  for (const Cell_handle& z : region_) {
    for (int i = 0; i < 4; ++i) {
      const Cell_handle n = z->neighbor(i);
      if (!n->tds_data().is_in_conflict()) boundary_.push_back({z, i, n, n->index(z)});
    }
  }
  if (!cone_is_regular(v, wp)) return false;
  new_worst = -std::numeric_limits<double>::infinity();
  for (const BoundaryFacet& f : boundary_) {
    const auto q = new_cell(f.inner, f.index, wp);
    // As cell_cosine() will see the new cell (cone_hole keeps the inner cell's vertex order).
    new_worst = std::max(new_worst, max_dihedral_cosine(to_point3(*q[0]), to_point3(*q[1]),
                                                        to_point3(*q[2]), to_point3(*q[3])));
  }
  return true;
}

bool VertexPerturber::cone_is_regular(Vertex_handle v, const Weighted_point& wp) {
  edges_.reset(3 * boundary_.size());
  boundary_vertices_.clear();
  for (std::size_t k = 0; k < boundary_.size(); ++k) {
    const BoundaryFacet& f = boundary_[k];
    const auto q = new_cell(f.inner, f.index, wp);
    if (CGAL::orientation(q[0]->point(), q[1]->point(), q[2]->point(), q[3]->point()) !=
        CGAL::POSITIVE)
      return false;
    // Regular across the facet that stays: the far vertex of the cell behind it.
    const Vertex_handle far = f.outer->vertex(f.outer_index);
    if (!tr_.is_infinite(far) && !strictly_outside(q, far->point())) return false;
    const Vertex_handle w[3] = {f.inner->vertex((f.index + 1) & 3),
                                f.inner->vertex((f.index + 2) & 3),
                                f.inner->vertex((f.index + 3) & 3)};
    for (int j = 0; j < 3; ++j) {
      boundary_vertices_.push_back(w[j]);
      edges_.add(w[j], w[(j + 1) % 3], static_cast<int>(k));
    }
  }
  // A closed surface: each edge on exactly two facets. And regular across the
  // new facets (p, a, b): the two new cells on the edge ab, each against the
  // far vertex of the other.
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const EdgeTable::Edge& edge = edges_[e];
    if (edge.count != 2) return false;
    const Vertex_handle c = third_vertex(boundary_[edge.facet[0]], edge.a, edge.b);
    const Vertex_handle d = third_vertex(boundary_[edge.facet[1]], edge.a, edge.b);
    for (const auto& [mine, other] : {std::pair{c, d}, std::pair{d, c}}) {
      // The new cell p + (a, b, mine), positively oriented.
      std::array<const Weighted_point*, 4> q = {&wp, &edge.a->point(), &edge.b->point(),
                                                &mine->point()};
      if (CGAL::orientation(q[0]->point(), q[1]->point(), q[2]->point(), q[3]->point()) !=
          CGAL::POSITIVE)
        std::swap(q[1], q[2]);
      if (!strictly_outside(q, other->point())) return false;
    }
  }
  // No vertex of R but v may vanish: all lie on the boundary.
  std::sort(boundary_vertices_.begin(), boundary_vertices_.end(), vertex_less);
  for (const Cell_handle& z : region_) {
    for (int k = 0; k < 4; ++k) {
      const Vertex_handle u = z->vertex(k);
      if (u != v &&
          !std::binary_search(boundary_vertices_.begin(), boundary_vertices_.end(), u, vertex_less))
        return false;
    }
  }
  return true;
}

void VertexPerturber::move(Vertex_handle v, const Point3& p, int label) {
  hole_facets_.clear();
  for (const BoundaryFacet& f : boundary_) hole_facets_.push_back({f.inner, f.index});
  // The new cells, in the order of the boundary facets.
  cone_.build(tr_, region_, hole_facets_, v, nullptr, new_cells_);
  v->set_point(weighted(p, v->point().weight()));
  for (const Cell_handle& c : new_cells_) {
    CellInfo& info = c->info();
    info.stamp = next_stamp_++;
    info.label = label;
    info.facet_patch.fill(kNotRestricted);
    info.shape_cosine = stored_shape(tr_, c);
  }
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
    double old_worst = 0, new_worst = 0;
    if (!plan_move(v, p, label, nearest, old_worst, new_worst)) continue;
    if (!(new_worst < old_worst)) continue;
    move(v, p, label);
    return true;
  }
  return false;
}

}  // namespace rdmesh::detail
