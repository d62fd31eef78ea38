#include "rdmesh/mesher.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "optimize/sliver_exuder.h"
#include "optimize/tet_improvement_entry.h"
#include "rdmesh/errors.h"
#include "rdmesh/number_text.h"
#include "rdmesh/stopwatch.h"
#include "rdmesh/tet_improvement.h"
#include "refiner.h"

namespace rdmesh {
namespace {

/// An empty mesh is an input error (criteria too coarse for the domain, like
/// those check_feasible refuses), a patch without triangles a warning in the stats.
void check_output(const DomainOracle& oracle, bool surface_only, MeshResult& result) {
  if (surface_only && result.mesh.triangles.empty()) {
    throw InputError("the surface gave no triangle at these sizes (its " +
                     std::to_string(result.stats.initial_points) +
                     " initial points capture none of it): give a smaller size");
  }
  if (!surface_only && result.mesh.tets.empty()) {
    // A valid domain thinner than the cells (a flat tetrahedron 0.016 thick
    // in a box of 2.2, found by fuzz/cli_campaign.py): no cell's centre lies
    // inside it. Once an exit 3.
    throw InputError("no tetrahedron has its centre inside the domain at these sizes (" +
                     std::to_string(result.mesh.triangles.size()) +
                     " boundary triangles): the domain is thinner than its cells, or its "
                     "features meet at angles too small to resolve above the minimum size");
  }
  std::set<int> present;
  for (const PatchId& p : result.mesh.triangle_patch) present.insert(p.value);
  for (const PatchInfo& patch : oracle.patches()) {
    if (!present.count(patch.id.value)) result.stats.missing_patches.push_back(patch.id);
  }
}

/// The protecting-ball planner for the oracle's curves and corners.
detail::ProtectionPlanner make_planner(const DomainOracle& oracle, const Criteria& criteria) {
  std::vector<detail::ProtectedCurve> curves;
  for (const CurveInfo& info : oracle.curves()) curves.push_back({info, &oracle.curve(info.id)});
  return detail::ProtectionPlanner(std::move(curves), oracle.corners(), criteria, criteria.min_size,
                                   &oracle);
}

void record_protection(const detail::ProtectionPlanner& planner, const detail::ProtectionPlan& plan,
                       const std::vector<detail::BallRef>& conflicts, RefinementStats& stats) {
  stats.protecting_balls = plan.balls;
  stats.min_ball_radius = plan.min_radius;
  stats.protection_conflicts = plan.unresolved_pairs + conflicts.size();
  stats.protection_features = plan.unresolved;
  // Curves whose balls (or whose corners' balls) could not be separated from
  // other features, or kept off a patch they do not bound, at the minimum size.
  std::set<int> below(plan.unresolved_curves.begin(), plan.unresolved_curves.end());
  for (const detail::BallRef& b : conflicts) {
    for (const int j : planner.curves_touching(b)) below.insert(j);
  }
  for (const int j : below) stats.curves_below_min_size.push_back(CurveId(j + 1));
  for (const detail::BallRef& b : conflicts) {
    if (stats.protection_features.size() >= RefinementStats::kMaxListed) break;
    const std::string what = planner.name(b) + " reaches a patch it does not bound";
    if (std::find(stats.protection_features.begin(), stats.protection_features.end(), what) ==
        stats.protection_features.end()) {
      stats.protection_features.push_back(what);
    }
  }
}

/// Tells the progress callback that `phase` starts.
void announce(const MeshOptions& options, const char* phase) {
  if (!options.progress) return;
  Progress p;
  p.phase = phase;
  options.progress(p);
}

}  // namespace

const char* phase_name(MeshingPhase phase) {
  switch (phase) {
    case MeshingPhase::protection:
      return "protection";
    case MeshingPhase::initial_points:
      return "initial points";
    case MeshingPhase::refinement:
      break;
  }
  return "refinement";
}

MeshResult generate_mesh(const DomainOracle& oracle, const Criteria& given,
                         const MeshOptions& options) {
  given.validate();
  Criteria criteria = given;  // the minimum size resolved once, for every stage
  criteria.min_size = given.min_size_for(oracle.bounding_box());
  if (!(options.time_limit_seconds >= 0) || !std::isfinite(options.time_limit_seconds)) {
    throw InputError("the time limit must be a number of seconds >= 0 (0: none), got " +
                     short_number(options.time_limit_seconds));
  }
  if (options.threads < 0) {
    throw InputError("the number of threads must be >= 0 (0: all cores), got " +
                     std::to_string(options.threads));
  }
  const Stopwatch run_clock;
  const auto deadline =
      options.time_limit_seconds > 0
          ? Stopwatch::Clock::now() + std::chrono::duration_cast<Stopwatch::Clock::duration>(
                                          std::chrono::duration<double>(options.time_limit_seconds))
          : Stopwatch::Clock::time_point::max();
  const bool protect = options.features == FeatureMethod::kProtectingBalls &&
                       !(oracle.curves().empty() && oracle.corners().empty());
  Stopwatch phase;
  std::optional<detail::ProtectionPlanner> planner;
  detail::ProtectionPlan plan;
  // A ball found reaching into a patch its feature does not bound is shrunk
  // and refinement starts again (it stops early, once the surface rules are
  // done, so a restart costs little). When no ball can shrink any more, or
  // after the last restart, the run goes on and the conflict is reported.
  constexpr int kMaxRestarts = 6;
  std::unique_ptr<detail::Refiner> refiner;
  double protect_seconds = 0, initial = 0, refine = 0;
  int restarts = 0;
  // The time limit covers the whole run: protection and the initial points
  // stop with TimeLimitReached (a needle 4e9 long protected down to its
  // minimum size once took 16 s at --time-limit 10), refinement with a flag.
  bool in_protection = false;
  try {
    if (protect) {
      announce(options, "protecting sharp features");
      in_protection = true;
      planner.emplace(make_planner(oracle, criteria));
      planner->set_deadline(deadline);
      plan = planner->plan();
      in_protection = false;
    }
    protect_seconds = phase.seconds();
    for (bool restart = true; restart;) {
      refiner =
          std::make_unique<detail::Refiner>(oracle, criteria, options, protect ? &plan : nullptr);
      refiner->set_deadline(deadline);
      phase.restart();
      announce(options, "inserting initial points");
      refiner->insert_initial_points();
      initial += phase.lap();
      announce(options, "refining");
      refiner->refine(protect && restarts < kMaxRestarts);
      restart = false;
      const bool out_of_time = refiner->stats().time_limit_reached;
      if (protect && restarts < kMaxRestarts && !refiner->conflicts().empty() && !out_of_time) {
        const Stopwatch shrinking;
        announce(options, "protecting sharp features");
        in_protection = true;
        restart = planner->shrink(refiner->conflicts(), plan);
        in_protection = false;
        protect_seconds += shrinking.seconds();
        if (restart) {
          ++restarts;
        } else {
          announce(options, "refining");
          refiner->refine();  // as small as the minimum size allows: finish this run
        }
      }
      refine += phase.seconds();
    }
  } catch (const detail::TimeLimitReached&) {
    MeshResult stopped;  // no mesh: what the run reached is the time limit
    if (refiner) stopped.stats = refiner->stats();
    stopped.stats.time_limit_reached = true;
    stopped.stats.stopped_in =
        in_protection ? MeshingPhase::protection : MeshingPhase::initial_points;
    stopped.stats.seconds_protect = in_protection ? phase.seconds() : protect_seconds;
    stopped.stats.seconds_initial = initial;
    return stopped;
  }

  MeshResult result;
  ExudationOptions exudation = options.exudation;
  if (options.time_limit_seconds > 0) {
    // Exudation gets what is left of the run's time (nothing after a stop).
    const double left = options.time_limit_seconds - run_clock.seconds();
    if (refiner->stats().time_limit_reached || left <= 0) exudation.enabled = false;
    if (exudation.time_limit_seconds <= 0 || exudation.time_limit_seconds > left) {
      exudation.time_limit_seconds = std::max(left, 1e-9);
    }
  }
  if (exudation.enabled && !options.surface_only) {
    announce(options, "exuding slivers");
    const detail::ChainEdges chains = refiner->chain_edges();
    result.exudation = detail::exude_slivers(refiner->triangulation(), criteria, exudation, &chains,
                                             options.threads);
  }

  phase.restart();
  announce(options, "extracting the mesh");
  // After exudation every cell holds its shape: the improvement reads it
  // from the extraction rather than computing it again.
  std::vector<double> cosines;
  const bool known_shape =
      result.exudation.ran && options.improvement.enabled && !options.surface_only;
  result.mesh = refiner->extract_mesh(known_shape ? &cosines : nullptr);
  result.stats = refiner->stats();
  if (protect) {
    record_protection(*planner, plan, refiner->conflicts(), result.stats);
    result.stats.protection_restarts = restarts;
  }
  result.stats.seconds_protect = protect_seconds;
  result.stats.seconds_initial = initial;
  result.stats.seconds_refine = refine;
  result.stats.seconds_extract = phase.seconds();
  // The triangulation is no longer needed: free it before the improvement,
  // which builds its own structures over the extracted mesh (peak memory).
  refiner.reset();
  // A run stopped by its time limit reports what it reached, even nothing.
  if (result.stats.time_limit_reached) return result;
  check_output(oracle, options.surface_only, result);
  TetImprovementOptions improvement = options.improvement;
  improvement.threads = options.threads;
  if (options.time_limit_seconds > 0) {
    // The improvement gets what is left of the run's time (nothing: it does not run).
    const double left = options.time_limit_seconds - run_clock.seconds();
    if (left <= 0) improvement.enabled = false;
    if (improvement.time_limit_seconds <= 0 || improvement.time_limit_seconds > left) {
      improvement.time_limit_seconds = std::max(left, 1e-9);
    }
  }
  if (improvement.enabled && !options.surface_only) {
    announce(options, "improving the tetrahedra");
    result.improvement = detail::improve_tets_of_known_shape(
        result.mesh, improvement,
        {&oracle, criteria.facet_distance, criteria.edge_size, criteria.facet_size},
        std::move(cosines));
  }
  return result;
}

}  // namespace rdmesh
