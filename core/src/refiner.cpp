// The refinement procedures of RR-7912 section 3:
//   refine-edge               insert the center of the edge's restricted Delaunay
//                             ball, on the curve;
//   refine-facet-or-edge      consider the center c_f of the facet's surface
//                             Delaunay ball: if it encroaches a restricted edge
//                             (lies inside its ball), refine that edge, else insert c_f;
//   refine-tet-facet-or-edge  consider the circumcenter c_t: encroached edges
//                             first, then encroached facets, else insert c_t.
// Rules apply in order: arcs (R1, R2) before facets (R3, R4) before cells (R5).
#include "refiner.h"

#include <algorithm>
#include <cmath>

#include "rdmesh/errors.h"
#include "rdmesh/feature_name.h"

namespace rdmesh::detail {

namespace {
/// RefinementStats::guard_features names at most this many pairs of features.
constexpr std::size_t kGuardFeaturesListed = 20;
}  // namespace

Refiner::Refiner(const DomainOracle& oracle, const Criteria& criteria, const MeshOptions& options,
                 const ProtectionPlan* plan)
    : oracle_(oracle),
      criteria_(criteria),
      options_(options),
      plan_(plan),
      complex_(oracle, options.surface_only),
      tr_(complex_.triangulation()),
      facets_(complex_, criteria_),
      cells_(complex_, criteria_) {
  const double min_size = criteria_.min_size_for(oracle_.bounding_box());
  min_size_sq_ = min_size * min_size;
  zone_cells_.reserve(64);
  zone_boundary_.reserve(128);
  new_cells_.reserve(128);
  start_time_ = std::chrono::steady_clock::now();
  load_curves();
}

void Refiner::insert_initial_points() {
  if (plan_) {
    insert_protecting_balls();
  } else {
    insert_corners_and_curve_samples();
  }
  Cell_handle hint;
  std::size_t offered = 0, kept_out = 0;  // patch points, and those the curves kept out
  for (const PatchInfo& patch : oracle_.patches()) {
    for (const Point3& p : oracle_.initial_points(patch.id)) {
      deadline_.check(256);
      ++offered;
      if (plan_) {
        // Nothing is ever inserted inside a protecting ball.
        if (!outside_balls(p, hint)) {
          ++kept_out;
          continue;
        }
      } else {
        // A patch point close to a curve would sit in the balls of its restricted
        // edges and force tiny arcs; the curve samples cover that area instead.
        bool near_curve = false;
        for (const CurveState& c : curves_) {
          const double t = c.curve->closest(p, c.info.t_begin, c.info.t_end);
          const double keep_out = 0.25 * criteria_.edge_size(p);
          near_curve = near_curve || squared_norm(c.curve->point(t) - p) < keep_out * keep_out;
        }
        if (near_curve) {
          ++kept_out;
          continue;
        }
      }
      const Vertex_handle v = tr_.insert(to_weighted(p), hint);
      if (v == Vertex_handle() || v->info().dim != FeatureDim::kVolume) continue;  // a duplicate
      v->info().dim = FeatureDim::kPatch;
      v->info().feature = patch.id.value;
      hint = v->cell();
      ++stats_.initial_points;
    }
  }
  if (tr_.dimension() < 3 && options_.surface_only) {
    // A flat surface: the corners of a box well around the domain give the
    // triangulation its third dimension. Far from the surface, their Voronoi
    // cells leave it as soon as it is sampled (R3 removes them from D|S).
    const Box3 box = oracle_.bounding_box();
    const Point3 c = box.center();
    const double r = box.diagonal();
    for (int k = 0; k < 8; ++k) {
      const Point3 p{c.x + (k & 1 ? r : -r), c.y + (k & 2 ? r : -r), c.z + (k & 4 ? r : -r)};
      hint = tr_.insert(to_weighted(p), hint)->cell();
    }
  }
  if (tr_.dimension() < 3 && kept_out > 0) {
    // A size so large that the curves' protecting balls (or, with R1/R2, the
    // keep-out around their samples) hold the patches' initial points: a lens
    // at --size 5 keeps three balls on its rim and nothing else.
    throw InputError(
        "the sizes are too large for this domain: the " +
        std::string(plan_ ? "protecting balls of the curves hold " : "curve samples keep out ") +
        std::to_string(kept_out) + " of the " + std::to_string(offered) +
        " initial points of the patches, and what is left spans no volume: "
        "give a smaller size");
  }
  if (tr_.dimension() < 3) {
    throw OracleError("the oracle's initial points span no volume (" +
                      std::to_string(stats_.initial_points) + " points): cannot start refinement");
  }
  complex_.init_unstamped_cells();
  for (auto c = tr_.all_cells_begin(); c != tr_.all_cells_end(); ++c) {
    for (int i = 0; i < 4; ++i) {
      if (c->neighbor(i)->info().stamp > c->info().stamp) update_facet(c, i);
    }
    cells_.consider(c);
  }
  if (plan_) return;  // the balls are D|L already: no arc is ever refined
  for (std::size_t j = 0; j < curves_.size(); ++j) {
    CurveState& c = curves_[j];
    for (auto a = c.samples.begin(); c.has_next(a); ++a) create_arc(static_cast<int>(j), a, true);
  }
}

void Refiner::refine(bool stop_on_conflict) {
  if (stop_on_conflict && plan_) {
    // The facets between the balls alone already show most balls that reach
    // a patch their feature does not bound (R3), and most overlaps that stray
    // from the surface: shrink them before any refinement work.
    for (auto c = tr_.finite_cells_begin(); c != tr_.finite_cells_end(); ++c) {
      for (int i = 0; i < 4; ++i) {
        if (c->info().facet_patch[i] != 0 && c->neighbor(i)->info().stamp > c->info().stamp) {
          if (facets_.violation(c, i).rule == Rule::kR3NotFaithful) ball_conflict(c, i);
          overlap_conflict(c, i);
        }
      }
    }
    if (!conflicts_.empty()) return;
  }
  for (;;) {
    if (!arc_queue_.empty()) {
      const ArcEntry e = arc_queue_.top();
      arc_queue_.pop();
      const std::optional<CurveState::Arc> a = find_arc(e.arc);
      // R1 entries stay valid while the arc exists.
      if (!a || (e.rule != Rule::kR1NotRestricted && !arc_violation(e.arc.curve, *a))) continue;
      refine_edge(e.arc.curve, *a);
    } else if (!facets_.empty()) {
      const std::optional<ElementEntry> e = facets_.pop();
      if (!e) continue;
      refine_facet_or_edge(e->cell, e->facet);
    } else if (!cells_.empty()) {
      if (stop_on_conflict && !conflicts_.empty()) break;  // the caller shrinks the balls
      const std::optional<ElementEntry> e = cells_.pop();
      if (!e) continue;
      refine_tet_facet_or_edge(*e);
    } else {
      break;
    }
    if (options_.progress && ++insertions_since_progress_ >= 4096) report_progress();
    if (deadline_.passed(256)) {
      stats_.time_limit_reached = true;
      stats_.stopped_in = MeshingPhase::refinement;
      stats_.elements_left = arc_queue_.size() + facets_.size() + cells_.size();
      break;
    }
  }
  if (options_.progress) report_progress();
  cells_.release_if_empty();
}

bool Refiner::refine_edge(int curve, CurveState::Arc a) {
  const CurveSample& s = a->second;
  const auto b = std::next(a);
  const VertexInfo info{FeatureDim::kCurve, curve + 1, s.t_center, -1};
  if (!(s.t_center > a->first && s.t_center < b->first)) {
    record_guard(info, s.vertex->info());  // the arc is too short to split
    return false;
  }
  const Weighted_point p = to_weighted(s.center);
  if (!find_conflict_zone(p, tr_.locate(p, s.vertex->cell()))) {
    record_guard(info, s.vertex->info());
    return false;
  }
  const double t = s.t_center;
  const Vertex_handle v = insert_in_zone(p, info);
  if (v == Vertex_handle()) return false;
  ++stats_.inserted_edge_centers;
  CurveState& c = curves_[curve];
  const auto mid = c.samples.emplace_hint(b, t, CurveSample{v, to_point3(v->point())});
  create_arc(curve, a, true);
  create_arc(curve, mid, true);
  return true;
}

bool Refiner::refine_facet_or_edge(Cell_handle c, int i) {
  const Point3 center = c->info().surface_center[i];
  const Weighted_point p = to_weighted(center);
  // The ball center lies on the dual Voronoi edge, hence inside the Delaunay
  // ball of at least one of the two incident cells.
  Cell_handle start = c;
  if (tr_.side_of_power_sphere(start, p) != CGAL::ON_BOUNDED_SIDE) start = c->neighbor(i);
  const VertexInfo info{FeatureDim::kPatch, c->info().facet_patch[i], 0, -1};
  if (plan_) {
    // A ball reaching into a patch its feature does not bound: R3 cannot be
    // met there until the ball shrinks. Other facets whose surface ball has no
    // positive radius lie inside the balls: protected, not refined.
    if (ball_conflict(c, i) || !(complex_.facet_power(c, i, center) > 0)) return false;
    // The guard before the conflict zone: the facet's vertices are vertices
    // of every cell in conflict, so one closer than the minimum size refuses
    // the point as insert_in_zone would, without the zone's cost (most of
    // the run where features lie closer than the minimum size).
    for (int k = 1; k < 4; ++k) {
      const Vertex_handle v = c->vertex((i + k) & 3);
      if (squared_norm(to_point3(v->point()) - center) < min_size_sq_) {
        record_guard(info, v->info());
        return false;
      }
    }
  }
  if (!find_conflict_zone(p, start)) {
    record_guard(info, c->vertex((i + 1) & 3)->info());  // the center coincides with a vertex
    return false;
  }
  if (!plan_) {
    if (const auto arc = encroached_arc(center)) {
      ++stats_.encroachments;
      return refine_edge(arc->first, arc->second);
    }
  }
  if (insert_in_zone(p, info) == Vertex_handle()) return false;
  ++stats_.inserted_facet_centers;
  return true;
}

bool Refiner::refine_tet_facet_or_edge(const ElementEntry& entry) {
  const Cell_handle c = entry.cell;
  const Point3 center = c->info().circumcenter;
  // An orthosphere of non-positive radius lies inside the protecting balls.
  if (plan_ && !(c->info().squared_radius > 0)) return false;
  const Weighted_point p = to_weighted(center);
  if (!find_conflict_zone(p, c)) return false;
  bool redirected = false, inserted = false;
  if (const auto arc = plan_ ? std::nullopt : encroached_arc(center)) {
    redirected = true;
    inserted = refine_edge(arc->first, arc->second);
  } else {
    Cell_handle fc;
    int fi = -1;
    if (encroached_facet(center, fc, fi)) {
      redirected = true;
      inserted = refine_facet_or_edge(fc, fi);
    }
  }
  if (redirected) {
    ++stats_.encroachments;
    // The cell may still need refining.
    if (inserted && complex_.is_live(entry.stamp)) cells_.requeue(entry);
    return inserted;
  }
  if (insert_in_zone(p, VertexInfo{}) == Vertex_handle()) return false;
  ++stats_.inserted_cell_centers;
  return true;
}

bool Refiner::encroached_facet(const Point3& x, Cell_handle& cell, int& facet) const {
  // A surface Delaunay ball lies in the union of its facet's two Delaunay
  // balls, so a ball containing x belongs to a facet of a conflict cell.
  double best = -1;
  for (const Cell_handle& z : zone_cells_) {
    for (int i = 0; i < 4; ++i) {
      if (z->info().facet_patch[i] == 0) continue;
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

bool Refiner::find_conflict_zone(const Weighted_point& p, Cell_handle start) {
  if (tr_.side_of_power_sphere(start, p) != CGAL::ON_BOUNDED_SIDE) start = tr_.locate(p, start);
  zone_cells_.clear();
  zone_boundary_.clear();
  zone_feature_vertices_.clear();
  tr_.find_conflicts(p, start, std::back_inserter(zone_boundary_), std::back_inserter(zone_cells_));
  // No arc to check for encroachment: protecting balls, or no curve at all.
  if (plan_ || curves_.empty()) return !zone_cells_.empty();
  for (const Cell_handle& z : zone_cells_) {
    for (int k = 0; k < 4; ++k) {
      const Vertex_handle v = z->vertex(k);
      if (tr_.is_infinite(v) || v->info().dim > FeatureDim::kCurve) continue;
      if (std::find(zone_feature_vertices_.begin(), zone_feature_vertices_.end(), v) ==
          zone_feature_vertices_.end()) {
        zone_feature_vertices_.push_back(v);
      }
    }
  }
  return !zone_cells_.empty();
}

Vertex_handle Refiner::insert_in_zone(const Weighted_point& p, const VertexInfo& info) {
  // Termination guard: the nearest vertex of p is a vertex of a conflict cell.
  const Point3 q = to_point3(p);
  for (const Cell_handle& z : zone_cells_) {
    for (int k = 0; k < 4; ++k) {
      const Vertex_handle v = z->vertex(k);
      if (!tr_.is_infinite(v) && squared_norm(to_point3(v->point()) - q) < min_size_sq_) {
        record_guard(info, v->info());
        return Vertex_handle();
      }
    }
  }
  for (const Cell_handle& z : zone_cells_) complex_.kill(z->info());  // entries become stale
  const Triangulation::Facet& f = zone_boundary_.front();
  const Vertex_handle v =
      tr_.insert_in_hole(p, zone_cells_.begin(), zone_cells_.end(), f.first, f.second);
  v->info() = info;
  after_insertion(v);
  if (!plan_) recheck_arcs_after(v);
  return v;
}

void Refiner::after_insertion(Vertex_handle v) {
  new_cells_.clear();
  tr_.incident_cells(v, std::back_inserter(new_cells_));
  const std::uint32_t first_new = complex_.next_stamp();
  // Each new cell's facet opposite v bounds the conflict zone: the cell
  // across it is old, hence labeled.
  for (const Cell_handle& c : new_cells_) complex_.init_cell(c, c->neighbor(c->index(v)));
  for (const Cell_handle& c : new_cells_) {
    for (int i = 0; i < 4; ++i) {
      // Facets between two new cells are visited once, from the older stamp.
      const std::uint32_t ns = c->neighbor(i)->info().stamp;
      if (ns < first_new || ns > c->info().stamp) update_facet(c, i);
    }
  }
  for (const Cell_handle& c : new_cells_) cells_.consider(c);
}

void Refiner::update_facet(Cell_handle c, int i) {
  if (complex_.update_facet(c, i)) facets_.consider(c, i);
}

std::string Refiner::describe(const VertexInfo& v) const {
  switch (v.dim) {
    case FeatureDim::kCorner:
      return feature_name(CornerId{v.feature});
    case FeatureDim::kCurve:
      return feature_name(CurveId{v.feature}, curves_[v.feature - 1].info.name);
    case FeatureDim::kPatch:
      return feature_name(PatchId{v.feature});
    case FeatureDim::kVolume:
      return "volume";
  }
  return "?";
}

void Refiner::record_guard(const VertexInfo& candidate, const VertexInfo& nearest) {
  ++stats_.guard_rejections;
  if (stats_.guard_features.size() >= kGuardFeaturesListed) return;
  const std::string what = describe(candidate) + " near " + describe(nearest);
  auto& list = stats_.guard_features;
  if (std::find(list.begin(), list.end(), what) == list.end()) list.push_back(what);
}

void Refiner::report_progress() {
  insertions_since_progress_ = 0;
  Progress p;
  p.vertices = tr_.number_of_vertices();
  p.edge_queue = arc_queue_.size();
  p.facet_queue = facets_.size();
  p.cell_queue = cells_.size();
  p.elapsed_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time_).count();
  options_.progress(p);
}

bool Refiner::ball_conflict(Cell_handle c, int i) {
  const int patch = c->info().facet_patch[i];
  const Point3 center = c->info().surface_center[i];
  for (int k = 1; k < 4; ++k) {
    const Vertex_handle v = c->vertex((i + k) & 3);
    const double w = v->point().weight();
    if (w == 0 || complex_.on_patch(v->info(), patch)) continue;
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

}  // namespace rdmesh::detail
