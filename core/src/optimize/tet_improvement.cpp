// improve_tets (rdmesh/tet_improvement.h): sweeps over the tetrahedra below
// the bound, worst first (ties by number). For each one still alive and still
// below it: the best legal flip among the removals of its six edges and the
// 2-3 flips of its four faces, if one strictly raises the smallest angle of
// what it replaces; else the smoothing of its free vertices; if it is still
// there and below the bound, a new vertex inside it and its neighbours.
// Given the exact surface, the vertices on one patch only slide along it, and
// those inside one chain of feature edges along their curve.
// Vertices keep their indices; new ones come after them.
#include "rdmesh/tet_improvement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "curve_smoothing.h"
#include "patch_smoothing.h"
#include "rdmesh/errors.h"
#include "rdmesh/stopwatch.h"
#include "tet_flips.h"
#include "tet_improvement_entry.h"
#include "tet_insertion.h"
#include "tet_shape.h"
#include "tet_smoothing.h"
#include "tet_topology.h"

namespace rdmesh {
namespace {

using detail::LocalChange;
using detail::TetTopology;

/// The smallest angle and the histogram of the smallest dihedral angles `quality` (degrees).
void measure(const std::vector<double>& quality, double& min_deg, DihedralHistogram& histogram,
             std::size_t& tets) {
  min_deg = quality.empty() ? 0 : std::numeric_limits<double>::infinity();
  histogram.fill(0);
  for (const double q : quality) {
    min_deg = std::min(min_deg, q);
    detail::add_to_histogram(histogram, q);
  }
  tets = quality.size();
}

/// The best flip touching tetrahedron t; false when none improves.
bool best_flip(const TetTopology& topo, int t, LocalChange& best) {
  const detail::Tet q = topo.tet(t);
  LocalChange change;
  bool found = false;
  for (const auto& e : kTetEdges) {
    if (detail::plan_edge_removal(topo, q[e[0]], q[e[1]], change) &&
        (!found || change.after > best.after)) {
      best = std::move(change);
      found = true;
    }
  }
  for (int i = 0; i < 4; ++i) {
    if (detail::plan_face_flip(topo, t, i, change) && (!found || change.after > best.after)) {
      best = std::move(change);
      found = true;
    }
  }
  return found;
}

}  // namespace

TetImprovementStats improve_tets(TetMesh& mesh, const TetImprovementOptions& options,
                                 const BoundarySurface& surface) {
  return detail::improve_tets_of_known_shape(mesh, options, surface, {});
}

TetImprovementStats detail::improve_tets_of_known_shape(TetMesh& mesh,
                                                        const TetImprovementOptions& options,
                                                        const BoundarySurface& surface,
                                                        std::vector<double> cosines) {
  if (!mesh.tet_mid_nodes.empty() || !mesh.tet_partition.empty()) {
    throw InputError("tetrahedra are improved before second-order nodes and partitions are made");
  }
  // The smallest dihedral angle of a tetrahedron is at most arccos(1/3) = 70.53 degrees.
  if (!(options.bound_deg > 0 && options.bound_deg <= 70.5) || options.max_sweeps < 0 ||
      options.threads < 0 || !(options.max_insertions >= 0) ||
      !std::isfinite(options.max_insertions) || !(options.time_limit_seconds >= 0) ||
      !std::isfinite(options.time_limit_seconds)) {
    throw InputError(
        "improvement options: the bound must be in (0, 70.5] degrees, the sweeps "
        ">= 0, the insertions a fraction >= 0, the time limit a number of "
        "seconds >= 0 and the threads >= 0 (0: all cores)");
  }
  const Stopwatch clock;
  const auto elapsed = [&] { return clock.seconds(); };
  TetImprovementStats stats;
  stats.ran = true;
  TetTopology topo(mesh, options.threads, std::move(cosines));
  std::optional<detail::PatchSurface> patches;
  std::vector<double> curve_parameters;  // of the vertices inside chains, found once
  if (surface.oracle && options.boundary_moves) {
    patches.emplace(mesh, *surface.oracle, surface.facet_distance, surface.edge_size,
                    surface.facet_size);
  }
  {
    // The tets' qualities before are the topology's: mesh.tets in order.
    std::vector<double> quality(mesh.tets.size());
    for (std::size_t t = 0; t < quality.size(); ++t) quality[t] = topo.quality(static_cast<int>(t));
    measure(quality, stats.min_dihedral_before_deg, stats.histogram_before, stats.tets_before);
  }
  const auto max_insertions =
      static_cast<std::size_t>(options.max_insertions * static_cast<double>(mesh.tets.size())) + 10;
  for (int sweep = 0; sweep < options.max_sweeps && !stats.time_limit_reached; ++sweep) {
    std::vector<std::pair<double, int>> bad;
    for (std::size_t t = 0; t < topo.size(); ++t) {
      const int id = static_cast<int>(t);
      if (topo.alive(id) && topo.quality(id) < options.bound_deg)
        bad.push_back({topo.quality(id), id});
    }
    if (bad.empty()) break;
    std::sort(bad.begin(), bad.end());
    ++stats.sweeps;
    std::size_t changes = 0;
    for (const auto& [q, t] : bad) {
      if (options.time_limit_seconds > 0 && elapsed() > options.time_limit_seconds) {
        stats.time_limit_reached = true;
        break;
      }
      if (!topo.alive(t) || !(topo.quality(t) < options.bound_deg)) continue;
      LocalChange change;
      if (best_flip(topo, t, change)) {
        (change.removed.size() == 2 && change.added.size() == 3 ? stats.face_flips
                                                                : stats.edge_removals)++;
        detail::apply(topo, change);
        ++changes;
        continue;
      }
      const detail::Tet vertices = topo.tet(t);
      for (const int v : vertices) {
        if (detail::smooth_vertex(topo, v)) {
          ++stats.vertex_moves;
          ++changes;
        } else if (patches && detail::smooth_on_patch(topo, *patches, v)) {
          ++stats.boundary_moves;
          ++changes;
        } else if (patches && detail::smooth_on_curve(topo, *patches, curve_parameters, v)) {
          ++stats.curve_moves;
          ++changes;
        }
      }
      Point3 where;
      if (topo.alive(t) && topo.quality(t) < options.insertion_bound_deg &&
          stats.vertex_insertions < max_insertions &&
          (detail::plan_insertion(topo, t, 1, topo.vertex_count(), where, change) ||
           detail::plan_insertion(topo, t, 2, topo.vertex_count(), where, change) ||
           detail::plan_insertion(topo, t, 3, topo.vertex_count(), where, change))) {
        const int v = topo.add_vertex(where);
        detail::apply(topo, change);
        (void)detail::smooth_vertex(topo, v);
        ++stats.vertex_insertions;
        ++changes;
      }
    }
    if (changes == 0) break;
  }
  topo.write_to(mesh);
  // The topology keeps every alive tet's quality up to date, in write_to's order.
  measure(topo.alive_qualities(), stats.min_dihedral_after_deg, stats.histogram_after,
          stats.tets_after);
  stats.seconds = elapsed();
  return stats;
}

}  // namespace rdmesh
