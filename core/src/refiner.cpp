// The refinement procedures of RR-7912 section 3, without curves (R3-R5):
//   refine-facet          insert the center of the facet's surface Delaunay ball;
//   refine-tet-or-facet   consider the cell's circumcenter c_t: if c_t lies in
//                         the surface Delaunay ball of a restricted facet (it
//                         "encroaches" it), refine that facet instead; else
//                         insert c_t.
// Rules apply in order: a facet rule (R3, R4) always runs before a cell rule (R5).
#include "refiner.h"

#include <cmath>

#include "rdmesh/errors.h"

namespace rdmesh::detail {

Refiner::Refiner(const DomainOracle& oracle, const Criteria& criteria, const MeshOptions& options)
    : oracle_(oracle), criteria_(criteria), options_(options) {
  const Box3 box = oracle_.bounding_box();
  const double margin = 0.05 * box.diagonal();
  clip_box_ = {box.lo - Point3{margin, margin, margin}, box.hi + Point3{margin, margin, margin}};
  const double min_size = criteria_.min_size > 0 ? criteria_.min_size : 1e-4 * box.diagonal();
  min_size_sq_ = min_size * min_size;
  const double s = std::sin(criteria_.facet_angle_deg * M_PI / 180.0);
  facet_shape_bound_ = 4.0 * s * s;
  cell_shape_bound_sq_ = criteria_.cell_radius_edge * criteria_.cell_radius_edge;
  zone_cells_.reserve(64);
  zone_boundary_.reserve(128);
  new_cells_.reserve(128);
  start_time_ = std::chrono::steady_clock::now();
}

void Refiner::insert_initial_points() {
  Cell_handle hint;
  for (const PatchInfo& patch : oracle_.patches()) {
    for (const Point3& p : oracle_.initial_points(patch.id)) {
      const Vertex_handle v = tr_.insert(to_weighted(p), hint);
      if (v == Vertex_handle()) continue;  // coincides with an existing point
      v->info().dim = FeatureDim::kPatch;
      v->info().feature = patch.id.value;
      hint = v->cell();
      ++stats_.initial_points;
    }
  }
  if (tr_.dimension() < 3) {
    throw OracleError("the oracle's initial points span no volume (" +
                      std::to_string(stats_.initial_points) +
                      " points): cannot start refinement");
  }
  for (auto c = tr_.all_cells_begin(); c != tr_.all_cells_end(); ++c) init_cell(c);
  for (auto c = tr_.all_cells_begin(); c != tr_.all_cells_end(); ++c) {
    for (int i = 0; i < 4; ++i) {
      if (c->neighbor(i)->info().stamp > c->info().stamp) update_facet(c, i);
    }
    const double badness = cell_badness(c);
    if (badness > 0) cell_queue_.push({badness, c->info().stamp, c, -1});
  }
}

void Refiner::refine() {
  for (;;) {
    if (!facet_queue_.empty()) {
      const QueueEntry e = facet_queue_.top();
      facet_queue_.pop();
      if (stale(e) || facet_badness(e.cell, e.facet) <= 0) continue;
      refine_facet(e.cell, e.facet);
    } else if (!cell_queue_.empty()) {
      const QueueEntry e = cell_queue_.top();
      cell_queue_.pop();
      if (stale(e) || cell_badness(e.cell) <= 0) continue;
      refine_tet(e);
    } else {
      break;
    }
    if (options_.progress && ++insertions_since_progress_ >= 4096) report_progress();
  }
  if (options_.progress) report_progress();
}

void Refiner::refine_facet(Cell_handle c, int i) {
  const Weighted_point p = to_weighted(c->info().surface_center[i]);
  // The ball center lies on the dual Voronoi edge, hence inside the Delaunay
  // ball of at least one of the two incident cells.
  Cell_handle start = c;
  if (tr_.side_of_power_sphere(start, p) != CGAL::ON_BOUNDED_SIDE) {
    start = c->neighbor(i);
    if (tr_.side_of_power_sphere(start, p) != CGAL::ON_BOUNDED_SIDE) start = tr_.locate(p, c);
  }
  const int patch = c->info().facet_patch[i];
  if (!find_conflict_zone(p, start)) {
    ++stats_.guard_rejections;  // the center coincides with a vertex
    return;
  }
  if (!insert_in_zone(p, FeatureDim::kPatch, patch)) return;
  ++stats_.inserted_facet_centers;
}

void Refiner::refine_tet(const QueueEntry& entry) {
  const Cell_handle c = entry.cell;
  const Point3 center = c->info().circumcenter;
  const Weighted_point p = to_weighted(center);
  Cell_handle start = c;
  if (tr_.side_of_power_sphere(start, p) != CGAL::ON_BOUNDED_SIDE) start = tr_.locate(p, c);
  if (!find_conflict_zone(p, start)) return;

  // refine-tet-or-facet: a surface Delaunay ball containing c_t is a facet of
  // a conflict cell (the ball lies in the union of its two cells' balls).
  Cell_handle enc_cell;
  int enc_facet = -1;
  double enc_radius = -1;
  for (const Cell_handle& z : zone_cells_) {
    for (int i = 0; i < 4; ++i) {
      if (z->info().facet_patch[i] == 0) continue;
      const Point3 sc = z->info().surface_center[i];
      const double r2 = squared_norm(to_point3(z->vertex((i + 1) & 3)->point()) - sc);
      if (squared_norm(center - sc) < r2 && r2 > enc_radius) {
        enc_cell = z;
        enc_facet = i;
        enc_radius = r2;
      }
    }
  }
  if (enc_facet >= 0) {
    ++stats_.encroachments;
    refine_facet(enc_cell, enc_facet);
    if (!stale(entry)) cell_queue_.push(entry);  // the cell may still need refining
    return;
  }
  if (insert_in_zone(p, FeatureDim::kVolume, 0)) ++stats_.inserted_cell_centers;
}

bool Refiner::find_conflict_zone(const Weighted_point& p, Cell_handle start) {
  zone_cells_.clear();
  zone_boundary_.clear();
  tr_.find_conflicts(p, start, std::back_inserter(zone_boundary_), std::back_inserter(zone_cells_));
  return !zone_cells_.empty();
}

bool Refiner::insert_in_zone(const Weighted_point& p, FeatureDim dim, int feature) {
  // Termination guard: the nearest vertex of p is a vertex of a conflict cell.
  const Point3 q = to_point3(p);
  for (const Cell_handle& z : zone_cells_) {
    for (int k = 0; k < 4; ++k) {
      const Vertex_handle v = z->vertex(k);
      if (!tr_.is_infinite(v) && squared_norm(to_point3(v->point()) - q) < min_size_sq_) {
        ++stats_.guard_rejections;
        return false;
      }
    }
  }
  for (const Cell_handle& z : zone_cells_) z->info().stamp = 0;  // entries become stale
  const Triangulation::Facet& f = zone_boundary_.front();
  const Vertex_handle v =
      tr_.insert_in_hole(p, zone_cells_.begin(), zone_cells_.end(), f.first, f.second);
  v->info().dim = dim;
  v->info().feature = feature;
  after_insertion(v);
  return true;
}

void Refiner::after_insertion(Vertex_handle v) {
  new_cells_.clear();
  tr_.incident_cells(v, std::back_inserter(new_cells_));
  const std::uint32_t first_new = next_stamp_;
  for (const Cell_handle& c : new_cells_) init_cell(c);
  for (const Cell_handle& c : new_cells_) {
    for (int i = 0; i < 4; ++i) {
      // Facets between two new cells are visited once, from the older stamp.
      const std::uint32_t ns = c->neighbor(i)->info().stamp;
      if (ns < first_new || ns > c->info().stamp) update_facet(c, i);
    }
  }
  for (const Cell_handle& c : new_cells_) {
    const double badness = cell_badness(c);
    if (badness > 0) cell_queue_.push({badness, c->info().stamp, c, -1});
  }
}

void Refiner::report_progress() {
  insertions_since_progress_ = 0;
  Progress p;
  p.vertices = tr_.number_of_vertices();
  p.facet_queue = facet_queue_.size();
  p.cell_queue = cell_queue_.size();
  p.elapsed_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time_).count();
  options_.progress(p);
}

}  // namespace rdmesh::detail
