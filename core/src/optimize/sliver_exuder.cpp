// The exudation driver: queue of vertices (by blocks, worst first), weight bounds, time
// limit and statistics. One vertex step is WeightPump (weight_pump.cpp).
#include "sliver_exuder.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <queue>
#include <string>
#include <vector>

#include "../triangulation_walks.h"
#include "cell_shape.h"
#include "cone_hole.h"
#include "exudation_lanes.h"
#include "rdmesh/errors.h"
#include "rdmesh/number_text.h"
#include "rdmesh/parallel_for.h"
#include "rdmesh/stopwatch.h"
#include "sliver_queue_order.h"
#include "tet_shape.h"
#include "vertex_perturber.h"
#include "weight_pump.h"

namespace rdmesh::detail {
namespace {

void validate(const ExudationOptions& o) {
  if (!(o.time_limit_seconds >= 0) || !std::isfinite(o.time_limit_seconds))
    throw InputError("exudation time limit must be >= 0 seconds (0 = none), got " +
                     short_number(o.time_limit_seconds));
  if (!(o.sliver_bound_deg > 0 && o.sliver_bound_deg <= 90))
    throw InputError("exudation sliver bound must be in (0, 90] degrees, got " +
                     short_number(o.sliver_bound_deg));
  if (!(o.max_weight_ratio >= 0 && o.max_weight_ratio < 1))
    throw InputError("exudation weight ratio must be in [0, 1), got " +
                     short_number(o.max_weight_ratio));
  if (!(o.perturb_bound_deg > 0 && o.perturb_bound_deg <= 90))
    throw InputError("perturbation bound must be in (0, 90] degrees, got " +
                     short_number(o.perturb_bound_deg));
  if (o.passes < 1)
    throw InputError("exudation passes must be >= 1, got " + std::to_string(o.passes));
  if (o.max_moves_per_vertex < 0)
    throw InputError("exudation moves per vertex must be >= 0, got " +
                     std::to_string(o.max_moves_per_vertex));
}

/// How many cells ahead domain_cosines() prefetches vertices.
constexpr std::size_t kVertexLookahead = 8;

/// Lowers `slot` to `value` if it is smaller; threads may race on one slot
/// (the result is their minimum whatever the order).
inline void lower_to(double& slot, double value) {
  std::atomic_ref<double> a(slot);
  double current = a.load(std::memory_order_relaxed);
  while (value < current && !a.compare_exchange_weak(current, value, std::memory_order_relaxed)) {
  }
}

/// Raises `slot` to `value` if it is larger (as lower_to).
inline void raise_to(double& slot, double value) {
  std::atomic_ref<double> a(slot);
  double current = a.load(std::memory_order_relaxed);
  while (value > current && !a.compare_exchange_weak(current, value, std::memory_order_relaxed)) {
  }
}

/// Lowers the nearest-neighbour distances (squared, by vertex index) of the
/// four vertices of a finite cell at points p to its edges' lengths: each
/// vertex once, to the shortest of its three edges (the array is read at
/// random: one access per vertex, not two per edge). Threads lower the same
/// vertex's distance: the minimum does not depend on their order.
inline void lower_nearest(Cell_handle c, const Point3 (&p)[4], std::vector<double>& nearest_sq) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  double shortest[4] = {kNone, kNone, kNone, kNone};
  for (int a = 0; a < 3; ++a) {
    for (int b = a + 1; b < 4; ++b) {
      const double d2 = squared_norm(p[a] - p[b]);
      shortest[a] = std::min(shortest[a], d2);
      shortest[b] = std::min(shortest[b], d2);
    }
  }
  for (int k = 0; k < 4; ++k)
    lower_to(nearest_sq[static_cast<std::size_t>(c->vertex(k)->info().index)], shortest[k]);
}

/// The finite cells in iteration order and the cosine of each domain cell
/// (-infinity for the others); returns the largest stamp of all cells.
/// `store`: computed on `threads` threads and stored on every cell as its
/// shape_cosine (the infinite cells' too), which the exuder's first call
/// does; later calls read the stored shapes (whoever creates a cell stores its
/// shape; self_check verifies them all at the end). `nearest_sq` (with
/// `store`): also lowered to the edges of every finite cell (lower_nearest),
/// in the same pass over the cells' vertices, which lie all over memory.
std::uint32_t domain_cosines(Triangulation& tr, int threads, bool store,
                             std::vector<Cell_handle>& cells, std::vector<double>& cosines,
                             std::vector<double>* nearest_sq = nullptr) {
  cells.clear();
  cells.reserve(tr.number_of_finite_cells());
  std::uint32_t max_stamp = 0;
  for (auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) {
    max_stamp = std::max(max_stamp, c->info().stamp);
    if (!tr.is_infinite(c))
      cells.push_back(c);
    else if (store)
      c->info().shape_cosine = -std::numeric_limits<double>::infinity();
  }
  cosines.resize(cells.size());
  parallel_for(cells.size(), threads, [&](std::size_t i) {
    const Cell_handle c = cells[i];
    if (!store) {
      cosines[i] = c->info().shape_cosine;
      return;
    }
    // The vertices lie all over memory: ask for those of a cell a few ahead.
    if (i + kVertexLookahead < cells.size())
      for (int k = 0; k < 4; ++k) __builtin_prefetch(&*cells[i + kVertexLookahead]->vertex(k));
    if (nearest_sq == nullptr) {
      cosines[i] = stored_shape(tr, c);
    } else {
      // As stored_shape (c is finite), from the points read once.
      Point3 p[4];
      for (int k = 0; k < 4; ++k) p[k] = to_point3(c->vertex(k)->point());
      lower_nearest(c, p, *nearest_sq);
      cosines[i] = c->info().label != 0 ? max_dihedral_cosine(p[0], p[1], p[2], p[3])
                                        : -std::numeric_limits<double>::infinity();
    }
    c->info().shape_cosine = cosines[i];
  });
  return max_stamp;
}

/// Minimum dihedral angle and histogram over the cells of D|O (`cosines` from
/// domain_cosines), summed from chunks on `threads` threads.
void measure(const std::vector<double>& cosines, int threads, double& min_deg,
             DihedralHistogram& histogram) {
  constexpr double kOutside = -std::numeric_limits<double>::infinity();
  std::vector<DihedralHistogram> parts(chunk_count(cosines.size()), DihedralHistogram{});
  std::vector<double> worsts(parts.size(), kOutside);
  for_chunks(cosines.size(), threads, [&](std::size_t k, std::size_t begin, std::size_t end) {
    // Summed here and stored once: neighbouring chunks' sums share cache lines,
    // and two threads writing them at every cell ran slower than one thread.
    double worst = kOutside;
    DihedralHistogram part{};
    for (std::size_t i = begin; i < end; ++i) {
      if (cosines[i] == kOutside) continue;
      worst = std::max(worst, cosines[i]);
      add_to_histogram(part, cosine_to_degrees(cosines[i]));
    }
    worsts[k] = worst;
    parts[k] = part;
  });
  histogram.fill(0);
  double worst = kOutside;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    worst = std::max(worst, worsts[k]);
    for (std::size_t b = 0; b < histogram.size(); ++b) histogram[b] += parts[k][b];
  }
  min_deg = std::isfinite(worst) ? cosine_to_degrees(worst) : 0.0;
}

struct QueuedVertex {
  std::uint64_t key;  ///< SliverQueueOrder's key when queued (larger = first)
  Vertex_handle vertex;
  bool operator<(const QueuedVertex& o) const { return key < o.key; }
};

/// Rounds of lanes in each pumping pass (the first cut across the longest
/// axis, the second across the next one), before the pass ends on the whole
/// triangulation with what they left.
constexpr int kLaneRounds = 2;
/// Cells a lane's pool holds when its round starts (it keeps the cells its
/// cones free: exudation removes more cells than it makes).
constexpr std::size_t kPoolCells = 64;

/// One worst-first loop's own state: a lane's (id >= 0), or that of a loop
/// over the whole triangulation (id -1).
struct Lane {
  Lane(Triangulation& tr, int lane, std::uint32_t first_stamp, const CellLimits& limits,
       const ChainEdges* chains)
      : id(lane), pump(tr, first_stamp, limits, chains), pool(tr) {}
  bool owns(Cell_handle c) const { return id < 0 || in_lane(c, id); }

  int id;
  WeightPump pump;
  CellPool pool;
  std::priority_queue<QueuedVertex> queue;
  StarWalk walk;
  std::vector<Cell_handle> star;  ///< scratch: the star of vertex star_of (-1: none)
  int star_of = -1;
  std::vector<QueuedVertex> deferred;  ///< entries left to the next round
  std::size_t tried = 0, accepted = 0;
  bool time_limit_reached = false;
};

/// What a step of the worst-first loop did: the cells it created when it
/// changed the mesh (else nullptr), or that the vertex must wait for a later
/// round (it reaches past its lane).
struct Stepped {
  const std::vector<Cell_handle>* created = nullptr;
  bool deferred = false;
};

class Exuder {
 public:
  Exuder(Triangulation& tr, const Criteria& criteria, const ExudationOptions& options,
         const ChainEdges* chains, int threads)
      : tr_(tr),
        threads_(threads),
        options_(options),
        chains_(chains),
        limits_{&criteria, options.keep_cell_size, options.keep_radius_edge},
        bound_cosine_(std::cos(options.sliver_bound_deg * M_PI / 180)) {}

  ExudationStats run() {
    clock_.restart();
    ExudationStats stats;
    stats.ran = true;
    // One pass over the cells gives the figures before, the first queue, the stored shapes,
    // the nearest neighbours and the first free stamp.
    index_vertices();
    std::uint32_t next_stamp =
        domain_cosines(tr_, threads_, /*store=*/true, cells_, cosines_, &nearest_sq_) + 1;
    measure(cosines_, threads_, stats.min_dihedral_before_deg, stats.histogram_before);
    next_stamp = pump_passes(stats, next_stamp, /*cosines_fresh=*/true);
    if (options_.perturb && !stats.time_limit_reached) {
      // Slivers the weights could not remove: move their volume vertices, then pump again.
      const double t = elapsed();
      VertexPerturber perturber(tr_, next_stamp);
      bound_cosine_ = std::cos(options_.perturb_bound_deg * M_PI / 180);
      Lane whole(tr_, -1, next_stamp, limits_, chains_);
      for (const QueuedVertex& e : requeue(false)) whole.queue.push(e);
      process(
          whole,
          [&](Lane& lane, Vertex_handle v, int, double& worst) {
            worst = worst_cosine(lane, v);
            return true;
          },
          [&](Lane&, Vertex_handle v, int) {
            Stepped s;
            if (v->info().dim() != FeatureDim::kVolume) return s;
            ++stats.perturb_moves_tried;
            if (!perturber.perturb(v, nearest_distance(v))) return s;
            ++stats.perturb_moves_accepted;
            s.created = &perturber.new_cells();
            return s;
          });
      stats.time_limit_reached = whole.time_limit_reached;
      DihedralHistogram histogram;
      domain_cosines(tr_, threads_, /*store=*/false, cells_, cosines_);
      measure(cosines_, threads_, stats.min_dihedral_after_perturb_deg, histogram);
      stats.perturb_seconds = elapsed() - t;
      if (!stats.time_limit_reached) {
        index_vertices();  // nearest neighbours moved (cells_ is fresh)
        find_nearest();
        pump_passes(stats, perturber.next_stamp(), /*cosines_fresh=*/false);
      }
    }
    domain_cosines(tr_, threads_, /*store=*/false, cells_, cosines_);
    measure(cosines_, threads_, stats.min_dihedral_after_deg, stats.histogram_after);
    cells_ = {};
    cosines_ = {};
    stats.seconds = elapsed();
    return stats;
  }

 private:
  /// Weight pumping in passes of rising sliver bound (the worst slivers first
  /// across the whole mesh, then the milder ones); returns the next free stamp.
  /// `cosines_fresh`: cells_ and cosines_ are those of the current triangulation.
  /// Each pass runs kLaneRounds rounds of kExudationLanes lanes (side by side
  /// on up to threads_ threads), each round on what the one before left, then
  /// a loop over the whole triangulation on the rest: the same work in the
  /// same order for any number of threads.
  std::uint32_t pump_passes(ExudationStats& stats, std::uint32_t next_stamp, bool cosines_fresh) {
    // Stars may have changed since the last pumping (perturbation): forget every worst cosine.
    star_version_.assign(moves_.size(), 1);
    worst_version_.assign(moves_.size(), 0);
    worst_.assign(moves_.size(), 0);
    std::vector<std::unique_ptr<Lane>> lanes;
    for (int l = 0; l < kExudationLanes; ++l)
      lanes.push_back(std::make_unique<Lane>(tr_, l, next_stamp, limits_, chains_));
    Lane whole(tr_, -1, next_stamp, limits_, chains_);
    const std::array<int, 3> axes = axes_by_extent(box_);
    const int passes = std::max(1, options_.passes);
    for (int pass = 1; pass <= passes && !stats.time_limit_reached; ++pass) {
      bound_cosine_ = std::cos(options_.sliver_bound_deg * pass / passes * M_PI / 180);
      std::vector<QueuedVertex> work = requeue(cosines_fresh && pass == 1);
      for (int round = 0; round < kLaneRounds && !work.empty() && !stats.time_limit_reached;
           ++round) {
        std::vector<Vertex_handle> vertices;
        vertices.reserve(work.size());
        for (const QueuedVertex& e : work) vertices.push_back(e.vertex);
        assign_lanes(tr_, vertices, axes[static_cast<std::size_t>(round)]);
        for (int l = 0; l < kExudationLanes; ++l) {
          Lane& lane = *lanes[static_cast<std::size_t>(l)];
          lane.pool.fill(kPoolCells);
          lane.pump.set_lane(l, &lane.pool, next_stamp + static_cast<std::uint32_t>(l),
                             kExudationLanes);
        }
        for (const QueuedVertex& e : work)
          lanes[e.vertex->info().lane == lane_bit(0) ? 0 : 1]->queue.push(e);
        parallel_tasks(lanes.size(), threads_, [&](std::size_t l) { pump(*lanes[l]); });
        work.clear();
        for (const std::unique_ptr<Lane>& lane : lanes) {
          stats.moves_tried_in_lanes += lane->tried;
          merge(*lane, stats);
          work.insert(work.end(), lane->deferred.begin(), lane->deferred.end());
          lane->deferred.clear();
          lane->queue = {};
          lane->pool.release();
          next_stamp = std::max(next_stamp, lane->pump.next_stamp());
        }
      }
      if (stats.time_limit_reached) break;
      whole.pump.set_lane(-1, nullptr, next_stamp, 1);
      for (const QueuedVertex& e : work) whole.queue.push(e);
      pump(whole);
      merge(whole, stats);
      next_stamp = whole.pump.next_stamp();
    }
    return next_stamp;
  }

  /// Weight pumping of the vertices queued in `lane`, worst first.
  void pump(Lane& lane) {
    process(
        lane,
        [&](Lane& l, Vertex_handle v, int id, double& worst) {
          // Kept while the star of v stays as it is (process() counts its changes).
          l.star_of = -1;
          if (worst_version_[id] != star_version_[id]) {
            if (!l.walk.cells_if(v, l.star, [&](Cell_handle c) { return l.owns(c); })) return false;
            double w = -std::numeric_limits<double>::infinity();
            for (const Cell_handle& c : l.star) w = std::max(w, c->info().shape_cosine);
            worst_[id] = w;
            worst_version_[id] = star_version_[id];
            l.star_of = id;  // the step may hand the star to the pump
          }
          worst = worst_[id];
          return true;
        },
        [&](Lane& l, Vertex_handle v, int id) {
          Stepped s;
          const double max_weight =
              v->info().ball_weight + options_.max_weight_ratio * nearest_sq_[id];
          const std::vector<Cell_handle>* star = l.star_of == id ? &l.star : nullptr;
          const WeightPump::Outcome outcome = l.pump.pump(v, max_weight, star, worst_[id]);
          s.deferred = outcome == WeightPump::Outcome::kDeferred;
          if (s.deferred) return s;
          ++l.tried;
          if (outcome != WeightPump::Outcome::kAccepted) return s;
          ++l.accepted;
          s.created = &l.pump.new_cells();
          return s;
        });
  }

  static void merge(Lane& lane, ExudationStats& stats) {
    stats.moves_tried += lane.tried;
    stats.moves_accepted += lane.accepted;
    stats.time_limit_reached = stats.time_limit_reached || lane.time_limit_reached;
    lane.tried = lane.accepted = 0;
  }

  double elapsed() const { return clock_.seconds(); }

  /// The worst-first loop over lane.queue: `worst_of(lane, v, id, worst)` sets
  /// the worst cosine of the domain cells around v, or returns false when
  /// v's star leaves the lane; `step(lane, v, id)` tries vertex v (a Stepped).
  /// A vertex is tried again only after its star changed. Vertices left for a
  /// later round go to lane.deferred.
  template <class Worst, class Step>
  void process(Lane& lane, Worst worst_of, Step step) {
    while (!lane.queue.empty()) {
      if (options_.time_limit_seconds > 0 && elapsed() > options_.time_limit_seconds) {
        lane.time_limit_reached = true;
        return;
      }
      const QueuedVertex top = lane.queue.top();
      lane.queue.pop();
      const Vertex_handle v = top.vertex;
      const int id = v->info().index;
      if (!dirty_[id] || moves_[id] >= options_.max_moves_per_vertex) continue;
      // The entry may be outdated: re-rank the vertex by its current star.
      double worst = 0;
      if (!worst_of(lane, v, id, worst)) {
        lane.deferred.push_back(top);
        continue;
      }
      if (!(worst > bound_cosine_)) continue;
      const QueuedVertex now = entry(worst, v);
      if (now.key < top.key) {
        lane.queue.push(now);
        continue;
      }
      dirty_[id] = 0;  // tried on this star: wait until the star changes
      const Stepped stepped = step(lane, v, id);
      if (stepped.deferred) {
        dirty_[id] = 1;
        lane.deferred.push_back(top);
        continue;
      }
      if (stepped.created == nullptr) continue;
      ++moves_[id];
      // Vertices of the new cells: their stars changed (every vertex of a
      // destroyed cell is one of them, none is hidden). In a lane, all are its own.
      for (const Cell_handle& c : *stepped.created) {
        for (int k = 0; k < 4; ++k) {
          const Vertex_handle u = c->vertex(k);
          if (!tr_.is_infinite(u) && !star_version_.empty()) ++star_version_[u->info().index];
        }
      }
      for (const Cell_handle& c : *stepped.created) {
        const double cosine = c->info().shape_cosine;  // -infinity outside the domain
        if (!(cosine > bound_cosine_)) continue;
        for (int k = 0; k < 4; ++k) {
          dirty_[c->vertex(k)->info().index] = 1;
          lane.queue.push(entry(cosine, c->vertex(k)));
        }
      }
    }
  }

  /// Distance from v to its nearest neighbour in the triangulation.
  double nearest_distance(Vertex_handle v) const {
    std::vector<Vertex_handle> adjacent;
    tr_.finite_adjacent_vertices(v, std::back_inserter(adjacent));
    double d2 = std::numeric_limits<double>::infinity();
    for (const Vertex_handle& u : adjacent)
      d2 = std::min(d2, squared_norm(to_point3(u->point()) - to_point3(v->point())));
    return std::sqrt(d2);
  }

  /// Queue entry of vertex v, whose worst domain cell has cosine `cosine`.
  QueuedVertex entry(double cosine, Vertex_handle v) const {
    return {order_.key(cosine, to_point3(v->point())), v};
  }

  /// Vertex ids, no moves yet, nearest-neighbour distances to be lowered,
  /// the vertices' box and the queue's order over it.
  void index_vertices() {
    int n = 0;
    box_ = Box3::empty();
    for (auto v = tr_.finite_vertices_begin(); v != tr_.finite_vertices_end(); ++v) {
      v->info().index = n++;
      box_.grow(to_point3(v->point()));
    }
    if (n > 0) order_ = SliverQueueOrder(box_.lo, box_.hi, static_cast<std::size_t>(n));
    nearest_sq_.assign(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
    moves_.assign(static_cast<std::size_t>(n), 0);
  }

  /// Nearest-neighbour distances over the six edges of every finite cell
  /// (cells_ must hold them; after index_vertices()): each edge is seen from
  /// each of its cells, which costs less than CGAL's edge iterator (it walks
  /// the cells around every edge to report it once).
  void find_nearest() {
    parallel_for(cells_.size(), threads_, [&](std::size_t i) {
      const Cell_handle c = cells_[i];
      Point3 p[4];
      for (int k = 0; k < 4; ++k) p[k] = to_point3(c->vertex(k)->point());
      lower_nearest(c, p, nearest_sq_);
    });
  }

  /// The vertices incident to a domain cell below the current bound, each
  /// with its worst cosine, in vertex order; resets dirty_ (`cosines_fresh`:
  /// cells_ and cosines_ are up to date).
  std::vector<QueuedVertex> requeue(bool cosines_fresh) {
    if (!cosines_fresh) domain_cosines(tr_, threads_, /*store=*/false, cells_, cosines_);
    const std::size_t n = moves_.size();
    dirty_.assign(n, 1);
    std::vector<double> worst(n, -std::numeric_limits<double>::infinity());
    parallel_for(cells_.size(), threads_, [&](std::size_t i) {
      const double cosine = cosines_[i];
      if (!(cosine > bound_cosine_)) return;
      for (int k = 0; k < 4; ++k) raise_to(worst[cells_[i]->vertex(k)->info().index], cosine);
    });
    std::vector<QueuedVertex> queued;
    for (auto v = tr_.finite_vertices_begin(); v != tr_.finite_vertices_end(); ++v) {
      const double w = worst[v->info().index];
      if (w > bound_cosine_) queued.push_back(entry(w, v));
    }
    return queued;
  }

  /// Worst cosine over the domain cells incident to v (their shape_cosine).
  static double worst_cosine(Lane& lane, Vertex_handle v) {
    lane.walk.cells(v, lane.star);
    double worst = -std::numeric_limits<double>::infinity();
    for (const Cell_handle& c : lane.star) worst = std::max(worst, c->info().shape_cosine);
    return worst;
  }

  Triangulation& tr_;
  int threads_;
  ExudationOptions options_;
  const ChainEdges* chains_;
  CellLimits limits_;
  double bound_cosine_;
  std::vector<double> nearest_sq_;
  /// By vertex index, each written only by the lane that owns the vertex.
  std::vector<int> moves_;   ///< accepted moves per vertex
  std::vector<char> dirty_;  ///< star changed since the vertex was last tried
  /// By vertex: changes of its star counted by process(); worst_ is its worst
  /// cosine as it was at change worst_version_ (pump passes).
  std::vector<std::uint32_t> star_version_, worst_version_;
  std::vector<double> worst_;
  Box3 box_ = Box3::empty();  ///< of the vertices, as index_vertices() found them
  SliverQueueOrder order_{Point3{}, Point3{}, 0};
  std::vector<Cell_handle> cells_;  ///< finite cells, scratch of domain_cosines
  std::vector<double> cosines_;
  Stopwatch clock_;
};

/// `shapes`: every cell's shape_cosine must be its stored_shape() (after exudation).
void check_invariants(const Triangulation& tr, bool shapes) {
  if (!tr.is_valid()) throw InternalError("exudation left an invalid regular triangulation");
  for (auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) {
    if (shapes && !(c->info().shape_cosine == stored_shape(tr, c)))
      throw InternalError("exudation: a cell's stored shape is not its shape, cell stamp " +
                          std::to_string(c->info().stamp));
    for (int i = 0; i < 4; ++i) {
      const Cell_handle n = c->neighbor(i);
      const int j = n->index(c);
      const PatchId patch = c->info().facet_patch[i];
      if (patch != n->info().facet_patch[j] ||
          (patch != kNotRestricted &&
           !(c->info().surface_center[i] == n->info().surface_center[j])))
        throw InternalError("exudation: the two sides of a facet disagree on its restricted data");
      if ((patch != kNotRestricted) != (c->info().label != n->info().label))
        throw InternalError(
            "exudation: labels differ across a non-restricted facet (or agree "
            "across a restricted one), cell stamp " +
            std::to_string(c->info().stamp));
    }
  }
}

}  // namespace

ExudationStats exude_slivers(Triangulation& tr, const Criteria& criteria,
                             const ExudationOptions& options, const ChainEdges* chains,
                             int threads) {
  validate(options);
  if (tr.dimension() < 3) return {};
  if (options.self_check) check_invariants(tr, /*shapes=*/false);
  ExudationStats stats = Exuder(tr, criteria, options, chains, threads).run();
  if (options.self_check) check_invariants(tr, /*shapes=*/true);
  return stats;
}

}  // namespace rdmesh::detail
