// Entry point of the refinement core (RR-7912, section 3).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "rdmesh/criteria.h"
#include "rdmesh/optimization.h"
#include "rdmesh/oracle.h"
#include "rdmesh/tet_mesh.h"

namespace rdmesh {

/// Snapshot handed to the progress callback.
struct Progress {
  /// The phase running: "protecting sharp features", "inserting initial points",
  /// "refining", "exuding slivers", "extracting the mesh" or "improving the tetrahedra". Each phase
  /// is announced as it starts, with zero counts; the counts come from the insertions.
  const char* phase = "refining";
  std::size_t vertices = 0;     ///< vertices in the triangulation
  std::size_t edge_queue = 0;   ///< restricted edges waiting (R1, R2)
  std::size_t facet_queue = 0;  ///< restricted facets waiting (R3, R4)
  std::size_t cell_queue = 0;   ///< cells waiting (R5)
  double elapsed_seconds = 0.0;
};

/// How sharp curves and corners enter the mesh.
enum class FeatureMethod {
  /// Protecting balls (weighted points) on corners and curves, sized before
  /// refinement so that non-consecutive balls are disjoint; rules R3-R5 never
  /// insert a point inside a ball. Terminates whatever angles features meet
  /// at (RR-7912 section 7, [CDR07]). The default.
  kProtectingBalls,
  /// RR-7912's own rules R1/R2 (refine-edge with the encroachment cascade).
  /// Needs the paper's angle hypothesis (features meeting at >= 90 degrees);
  /// elsewhere the minimum-size guard ends the run.
  kRefineEdges,
};

struct MeshOptions {
  /// Called as each phase starts and, while refining, every few thousand insertions (and
  /// once at the end), from the calling thread.
  std::function<void(const Progress&)> progress;
  /// Sliver exudation after refinement (on by default).
  ExudationOptions exudation;
  /// Local improvement of the extracted tetrahedra (on by default; rdmesh/tet_improvement.h):
  /// the output is then no longer the restricted (weighted) Delaunay triangulation.
  TetImprovementOptions improvement;
  FeatureMethod features = FeatureMethod::kProtectingBalls;
  /// Mesh the patches only (D|S and D|L, no tetrahedra): every facet whose
  /// dual Voronoi edge crosses a patch is restricted, whatever the labels at
  /// its ends, so open surfaces work (the oracle's intersect() must then find
  /// a crossing of any segment that crosses a patch, as TriangleMeshOracle's
  /// does). Rules R1-R4 only; no cell label, no exudation. The output has no
  /// tetrahedra; its triangles are oriented consistently on each connected,
  /// orientable piece.
  bool surface_only = false;
  /// Stop refinement once the run (from the call of generate_mesh) has taken
  /// this many seconds; 0: no limit. The mesh is then what refinement reached
  /// (RefinementStats::time_limit_reached says so); exudation gets what is
  /// left of the time, if anything.
  double time_limit_seconds = 0;
  /// Threads of the phases that use them (0: all cores). The output does not
  /// depend on it: parallel work is split and combined by fixed rules.
  int threads = 0;
  /// Whether the oracle answers queries from several threads at once (its
  /// contract, rdmesh/oracle.h). False for oracles that call back into an
  /// interpreter holding a lock on the meshing thread (Python callables):
  /// then every oracle query stays on the calling thread (same output).
  bool oracle_concurrent = true;
};

/// The phases a time limit can stop (RefinementStats::stopped_in).
enum class MeshingPhase { protection, initial_points, refinement };
/// "protection", "initial points", "refinement": as messages and the report name them.
const char* phase_name(MeshingPhase phase);

/// What refinement did, for the report.
struct RefinementStats {
  /// The most entries a list of features below holds (guard_features,
  /// protection_features): a report names examples, not every pair.
  static constexpr std::size_t kMaxListed = 20;

  std::size_t initial_points = 0;
  std::size_t inserted_edge_centers = 0;   ///< points inserted on curves by R1/R2
  std::size_t inserted_facet_centers = 0;  ///< points inserted by R3/R4
  std::size_t inserted_cell_centers = 0;   ///< points inserted by R5
  std::size_t encroachments = 0;           ///< points redirected to an encroached facet or edge
  /// Of inserted_cell_centers, those the refinement lanes inserted (two parts
  /// of space side by side, on up to two threads), and their rounds.
  std::size_t cell_centers_in_lanes = 0;
  /// Of inserted_facet_centers, those the lanes inserted.
  std::size_t facet_centers_in_lanes = 0;
  std::size_t lane_rounds = 0;
  std::size_t lane_steps = 0;  ///< steps of those rounds (the lanes' pools topped up before each)
  /// Threads the lanes ran on (0: no round). One when MeshOptions::threads is,
  /// or when the oracle, the cell size, the facet size or the facet distance
  /// may not be called from several threads at once
  /// (MeshOptions::oracle_concurrent, ScalarField::is_concurrent).
  int lane_threads = 0;
  std::size_t guard_rejections = 0;  ///< refinement points refused by the minimum-size guard
  bool guard_fired() const { return guard_rejections > 0; }
  /// The features involved in guard rejections, e.g. "curve 2 near patch 3"
  /// (distinct pairs, at most kMaxListed).
  std::vector<std::string> guard_features;
  /// Restricted edges left out of the output because an endpoint is in no tetrahedron.
  std::size_t unmeshed_feature_edges = 0;
  /// Patches the oracle lists but no output triangle carries (a component the
  /// initial points missed, or a patch too small for the criteria).
  std::vector<PatchId> missing_patches;
  /// Protecting balls (FeatureMethod::kProtectingBalls; zero otherwise).
  std::size_t protecting_balls = 0;
  double min_ball_radius = 0.0;
  /// Refinement restarts with smaller balls: a ball reached into a patch its
  /// feature does not bound (at most MeshOptions' limit, see generate_mesh).
  int protection_restarts = 0;
  /// Pairs of balls still closer than the protection asks after their curve
  /// pieces reached the minimum size, plus balls still reaching into a patch
  /// after the last restart; the features involved (at most kMaxListed).
  std::size_t protection_conflicts = 0;
  std::vector<std::string> protection_features;
  /// Curves lying closer to another feature than the minimum size lets the
  /// mesh separate (a ball of theirs in an unresolved pair): below what the
  /// run can resolve, so the mesh may not follow them (ascending).
  std::vector<CurveId> curves_below_min_size;
  /// Refinement stopped at MeshOptions::time_limit_seconds with elements
  /// still to refine (`elements_left`: edges, facets and cells in the queues,
  /// some of them no longer bad).
  bool time_limit_reached = false;
  std::size_t elements_left = 0;
  /// Where the time limit stopped the run (with time_limit_reached): in
  /// refinement, or before any mesh.
  MeshingPhase stopped_in = MeshingPhase::refinement;
  double seconds_protect = 0.0;  ///< sizing the balls (all rounds)
  double seconds_initial = 0.0;
  double seconds_refine = 0.0;
  double seconds_extract = 0.0;
};

struct MeshResult {
  TetMesh mesh;
  RefinementStats stats;
  ExudationStats exudation;         ///< ran == false when disabled
  TetImprovementStats improvement;  ///< ran == false when disabled
};

/// Runs Delaunay refinement on `oracle` until every rule R3-R5 is satisfied
/// (or the guard stops it) and returns the restricted mesh D|O with D|S.
/// Throws InputError for invalid criteria, OracleError when the oracle fails
/// or the result has no tetrahedron at all (no triangle at all with
/// surface_only: the oracle's initial points do not capture the domain).
MeshResult generate_mesh(const DomainOracle& oracle, const Criteria& criteria,
                         const MeshOptions& options = {});

}  // namespace rdmesh
