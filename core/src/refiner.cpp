// The refinement of RR-7912 section 3 put together: P_0, then the scheduler
// (refinement_scheduler.h) runs the levels' procedures
//   refine-edge               insert the center of the edge's restricted Delaunay
//                             ball, on the curve (level_curves.cpp);
//   refine-facet-or-edge      consider the center c_f of the facet's surface
//                             Delaunay ball: if it encroaches a restricted edge
//                             (lies inside its ball), refine that edge, else insert
//                             c_f (level_facets.cpp);
//   refine-tet-facet-or-edge  consider the circumcenter c_t: encroached edges
//                             first, then encroached facets, else insert c_t
//                             (level_cells.cpp);
// and after each insertion the refiner updates the complex and the queues.
#include "refiner.h"

#include <algorithm>
#include <cmath>

#include "rdmesh/errors.h"

namespace rdmesh::detail {

namespace {
/// Progress is reported every this many refinement steps.
constexpr std::size_t kProgressEvery = 4096;

std::unique_ptr<CurveLevel> make_curve_level(const ProtectionPlan* plan, RestrictedCurves& curves,
                                             RestrictedComplex& complex, const DomainOracle& oracle,
                                             const Criteria& criteria) {
  if (plan) return std::make_unique<ProtectingBallsLevel>(*plan, curves, complex, oracle, criteria);
  return std::make_unique<CurveRefinementLevel>(curves, complex, criteria);
}
}  // namespace

Refiner::Refiner(const DomainOracle& oracle, const Criteria& criteria, const MeshOptions& options,
                 const ProtectionPlan* plan)
    : oracle_(oracle),
      criteria_(criteria),
      options_(options),
      complex_(oracle, options.surface_only),
      tr_(complex_.triangulation()),
      curves_(oracle),
      insertion_(complex_, curves_, criteria_.min_size_for(oracle.bounding_box()), stats_),
      curve_level_(make_curve_level(plan, curves_, complex_, oracle, criteria_)),
      facets_(complex_, criteria_),
      cells_(complex_, criteria_),
      scheduler_(*curve_level_, facets_, cells_, insertion_),
      lanes_(complex_, cells_, facets_, *curve_level_, criteria_,
             criteria_.min_size_for(oracle.bounding_box()),
             options.oracle_concurrent ? options.threads : 1,
             // Surface balls in the lanes only on smooth domains: with curves
             // and corners the changed order of the surface's insertions
             // gave worse meshes on test inputs (see core/README.md).
             oracle.corners().empty() && oracle.curves().empty()) {
  complex_.set_feature_patches(curves_.corner_patches(), curves_.curve_patches());
  insertion_.set_observer(this);
  new_cells_.reserve(128);
  start_time_ = std::chrono::steady_clock::now();
}

void Refiner::insert_initial_points() {
  // 1. The features: corners and curve samples, or the protecting balls.
  curve_level_->insert_initial_points(deadline_, stats_);
  // 2. At least three points on every patch, outside what the curves keep out.
  const PatchPoints patch_points = insert_patch_points();
  // 3. A volume to refine, or an error saying why there is none.
  if (tr_.dimension() < 3 && options_.surface_only) lift_flat_surface(patch_points.hint);
  if (tr_.dimension() < 3 && patch_points.kept_out > 0) {
    // A size so large that the curves' protecting balls (or, with R1/R2, the
    // keep-out around their samples) hold the patches' initial points: a lens
    // at --size 5 keeps three balls on its rim and nothing else.
    throw InputError("the sizes are too large for this domain: the " +
                     curve_level_->keep_out_reason() + std::to_string(patch_points.kept_out) +
                     " of the " + std::to_string(patch_points.offered) +
                     " initial points of the patches, and what is left spans no volume: "
                     "give a smaller size");
  }
  if (tr_.dimension() < 3) {
    throw OracleError("the oracle's initial points span no volume (" +
                      std::to_string(stats_.initial_points) + " points): cannot start refinement");
  }
  // 4. The restricted complex of P_0, and the levels' first queues (the cells
  // in the lanes' queues where a lane owns them).
  complex_.init_unstamped_cells();
  lanes_.start();
  for (auto c = tr_.all_cells_begin(); c != tr_.all_cells_end(); ++c) {
    for (int i = 0; i < 4; ++i) {
      if (c->neighbor(i)->info().stamp > c->info().stamp) update_facet(c, i);
    }
    cells_.consider(c);
  }
  curve_level_->queue_initial_arcs();
}

Refiner::PatchPoints Refiner::insert_patch_points() {
  PatchPoints count;
  Cell_handle& hint = count.hint;
  for (const PatchInfo& patch : oracle_.patches()) {
    for (const Point3& p : oracle_.initial_points(patch.id)) {
      deadline_.check(Deadline::kCheckEvery);
      ++count.offered;
      if (curve_level_->keeps_out(p, hint)) {
        ++count.kept_out;
        continue;
      }
      const Vertex_handle v = tr_.insert(to_weighted(p), hint);
      if (v == Vertex_handle() || v->info().dim() != FeatureDim::kVolume) continue;  // a duplicate
      v->info().feature = FeatureRef(patch.id);
      hint = v->cell();
      ++stats_.initial_points;
    }
  }
  return count;
}

void Refiner::lift_flat_surface(Cell_handle hint) {
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

void Refiner::refine(bool stop_on_conflict) {
  if (stop_on_conflict && curve_level_->find_early_conflicts(facets_)) return;
  for (;;) {
    const RefinementScheduler::Step step = scheduler_.step(stop_on_conflict);
    if (step == RefinementScheduler::Step::kStale) continue;
    if (step == RefinementScheduler::Step::kDone && lanes_.pending()) {
      // The sequential steps are done: the lanes refine their cells.
      if (stop_on_conflict && curve_level_->has_conflicts()) break;
      const bool late = lanes_.round(stats_, deadline_);
      if (options_.progress) report_progress();
      if (late || deadline_.passed(1)) {
        stop_at_time_limit();
        break;
      }
      continue;
    }
    if (step != RefinementScheduler::Step::kRefined) break;
    if (options_.progress && ++insertions_since_progress_ >= kProgressEvery) report_progress();
    if (deadline_.passed(Deadline::kCheckEvery)) {
      stop_at_time_limit();
      break;
    }
  }
  if (options_.progress) report_progress();
  cells_.release_if_empty();
}

void Refiner::stop_at_time_limit() {
  stats_.time_limit_reached = true;
  stats_.stopped_in = MeshingPhase::refinement;
  stats_.elements_left = scheduler_.queued();
}

void Refiner::zone_found(const std::vector<Cell_handle>& zone) { curve_level_->zone_found(zone); }

void Refiner::inserted(Vertex_handle v) {
  walk_.cells(v, new_cells_);
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
  curve_level_->inserted(v);
}

void Refiner::update_facet(Cell_handle c, int i) {
  if (complex_.update_facet(c, i)) facets_.consider(c, i);
}

void Refiner::report_progress() {
  insertions_since_progress_ = 0;
  Progress p;
  p.vertices = tr_.number_of_vertices();
  p.edge_queue = curve_level_->size();
  p.facet_queue = facets_.size();
  p.cell_queue = cells_.size();
  p.elapsed_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time_).count();
  options_.progress(p);
}

}  // namespace rdmesh::detail
