#include "refinement_lanes.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "optimize/exudation_lanes.h"
#include "rdmesh/parallel_for.h"

namespace rdmesh::detail {

namespace {
/// A lane refines at most twice what it had queued at the start of a round,
/// and at least this many elements (then the cut moves). No upper bound: a
/// round's set-up reads every queued entry's cell and vertices, all over
/// memory, on the meshing thread, and at 9.4 M tets a bound of 2^17 per lane
/// made 5 rounds of 1 to 3.7 M entries each (2.3 s, a sixth of the refinement
/// on two threads) where 1 round now does the same work.
constexpr std::size_t kMinQuota = 1 << 12;
/// A round ends when one lane has stopped (its queue empty or its quota done)
/// while the other still has this many elements queued: cut again through the
/// median of what is left, rather than let the other lane go on alone.
constexpr std::size_t kRebalance = 1 << 13;
/// A lane's pools hold the cells, vertices and stamps of as many insertions
/// as a sixteenth of the elements it has queued (it inserts about one for six),
/// within these bounds.
constexpr std::size_t kQueuedPerStep = 16;
constexpr std::size_t kMinStep = 1 << 6;
constexpr std::size_t kMaxStep = 1 << 12;
/// Pool cells per insertion: a cone has about 6.5 cells more than its zone.
constexpr std::size_t kCellsPerInsertion = 7;
/// The cuts an entry's zone crossed, in ElementEntry::facet: a cell's is
/// -1 - crossings, a facet's its index plus 4 * crossings. After kMaxCrossings,
/// the sequential steps take it.
constexpr int kMaxCrossings = 2;
bool is_facet(const ElementEntry& e) { return e.facet >= 0; }
int facet_index(const ElementEntry& e) { return e.facet & 3; }
int crossings(const ElementEntry& e) { return is_facet(e) ? e.facet >> 2 : -1 - e.facet; }
ElementEntry as_crossed(ElementEntry e) {
  e.facet = is_facet(e) ? e.facet + 4 : e.facet - 1;
  return e;
}
/// The entry as the levels know it (no crossing mark).
ElementEntry plain(ElementEntry e) {
  e.facet = is_facet(e) ? facet_index(e) : -1;
  return e;
}
/// The rounds cut across the third longest axis too when it is at least this
/// fraction of the longest. A zone across two cuts in a row is often inside a
/// lane at the third; after kMaxCrossings the sequential steps take it. Unit
/// sphere, 147 k tets on two threads: 2.7 k sequential insertions instead of
/// 3.6 k (two axes, one crossing), run time 0.28 s against 0.29 s (medians of 12).
constexpr double kShortAxis = 0.5;
/// A conflict zone seldom reaches further from the centre than this many radii.
constexpr double kBallReach = 3.0;
/// Tetrahedra the criteria give over the box of a block of the lanes' cell
/// queues (estimate_elements, which counts about twice a sphere's tets in its
/// box), at least. A lane refines its blocks one after the other, in Morton
/// order, so that its insertions read and write cells nearby in memory; in
/// strict priority order they read cold cells once the mesh outgrows the
/// cache. Unit sphere, one thread, 9.4 M tets (experiment runs of one
/// session, alternated): refinement 18.2-18.3 s with 512 blocks
/// (35 k estimated tets each), 21.8 s with 64, 20.1 s with 4096, 22.6-24.0 s
/// with one; 0.6% more tets with 512 blocks, 1.2% with 4096. At 1.2 M tets,
/// 64 blocks: 0.6% more tets, 2.0 s against 2.2-2.4 s.
constexpr double kEstimatedTetsPerBlock = 1 << 15;
/// At most 4096 blocks (a queue each, kept in every lane).
constexpr int kMaxBlockBits = 12;
/// Cells with a radius above the domain's extent over this stay sequential:
/// the coarse start of refinement, whose zones cross any cut.
constexpr double kCoarse = 16.0;
/// Stamps per insertion: every cell of a cone gets one (about 25 on average).
constexpr std::uint32_t kStampsPerInsertion = 32;
/// Slack for the insertions that create more than the averages above.
constexpr std::size_t kSlack = 2048;
}  // namespace

struct RefinementLanes::Lane {
  Lane(Triangulation& tr, int lane, const Deadline& run_deadline)
      : id(lane), pool(tr), deadline(run_deadline) {}

  struct FoundFacet {
    Cell_handle cell;
    int facet;
    std::uint32_t stamp;
  };

  int id;
  CellPool pool;
  std::vector<Vertex_handle> vertices;  ///< the vertices it may insert
  RestrictedComplex::StampBlock stamps;
  Deadline deadline;
  bool out_of_time = false;
  bool full = false;  ///< stopped in a step for want of pool, quota left
  std::size_t inserted = 0;
  std::size_t quota = 0;               ///< insertions this round at most
  std::size_t step = 0;                ///< insertions per step at most
  std::size_t step_quota = 0;          ///< insertions the pools hold in this step
  std::size_t step_end = 0;            ///< `inserted` at which the step ends
  std::vector<ElementEntry> deferred;  ///< for the sequential steps
  std::vector<ElementEntry> crossed;   ///< zones across the cut, for the next round
  std::vector<FoundFacet> facets;      ///< facets of D|S it leaves to the facet level
  std::size_t inserted_facets = 0;     ///< of `inserted`, facet centres
  // Scratch.
  ConflictWalk walk;
  ConeBuilder cone;
  std::vector<Cell_handle> zone, created;
  std::vector<Triangulation::Facet> boundary;
  std::vector<HoleFacet> hole;
};

RefinementLanes::RefinementLanes(RestrictedComplex& complex, CellLevel& cells, FacetLevel& facets,
                                 const CurveLevel& curves, const Criteria& criteria,
                                 double min_size, int threads, bool smooth)
    : complex_(complex),
      tr_(complex.triangulation()),
      cells_(cells),
      facets_(facets),
      curves_(curves),
      criteria_(criteria),
      min_size_sq_(min_size * min_size),
      threads_(criteria.cell_size.is_concurrent() ? threads : 1),
      // A facet size or facet distance that may not be called from two
      // threads keeps the facets in the sequential steps, not the cells.
      surface_(smooth && criteria.facet_size.is_concurrent() &&
               criteria.facet_distance.is_concurrent()) {}

void RefinementLanes::start() {
  const Box3 box = vertex_box(tr_);
  axes_ = axes_by_extent(box);
  // Every axis at least half as long as the longest takes its turn (at least
  // two): a cut across a short axis would cross a long part's every zone.
  cut_axes_ = extent(box, axes_[2]) >= kShortAxis * extent(box, axes_[0]) ? 3 : 2;
  const int axis = axes_[0];
  std::vector<double> values;
  for (auto v = tr_.finite_vertices_begin(); v != tr_.finite_vertices_end(); ++v)
    values.push_back(coordinate(to_point3(v->point()), axis));
  cut_ = cut_at(tr_, axis, median(values));
  const double reach = extent(box, axis) / kCoarse;
  const double tets = estimate_elements(criteria_, box, 0).tetrahedra;
  blocks_ = MortonBlocks(box.lo, box.hi,
                         MortonBlocks::bits_for(tets, kEstimatedTetsPerBlock, kMaxBlockBits));
  for (int l = 0; l < 2; ++l) cells_.lane_queue(l).set_blocks(&blocks_);
  cells_.set_lanes(true, reach * reach, &cut_);
  facets_.set_lanes(surface_, reach * reach, &cut_);
}

bool RefinementLanes::pending() const {
  return !cells_.lane_queue(0).empty() || !cells_.lane_queue(1).empty() ||
         !facets_.lane_queue(0).empty() || !facets_.lane_queue(1).empty() || !crossed_.empty() ||
         !cells_.parked().empty() || !facets_.parked().empty();
}

Point3 RefinementLanes::centre_of(const ElementEntry& e) {
  return is_facet(e) ? e.cell->info().surface_center[facet_index(e)] : e.cell->info().circumcenter;
}

bool RefinementLanes::round(RefinementStats& stats, const Deadline& deadline) {
  ++rounds_;
  ++stats.lane_rounds;
  stats.lane_threads = std::min(resolve_threads(threads_), 2);
  // 1. A new cut through the middle of the queued facets' and cells' centres.
  // (The sequential steps since the last round may have destroyed the cells
  // of crossed entries: a dead entry's cell is not read.)
  std::vector<ElementEntry> entries;
  for (const ElementEntry& e : crossed_)
    if (complex_.is_live(e.stamp)) entries.push_back(e);
  crossed_.clear();
  for (std::vector<ElementEntry>* parked : {&facets_.parked(), &cells_.parked()}) {
    for (const ElementEntry& e : *parked)
      if (complex_.is_live(e.stamp)) entries.push_back(e);
    parked->clear();
  }
  // The lanes' queues, emptied side by side (each task its own), then listed
  // lane after lane; the centres and owners below are read in parallel loops
  // too. (1.18 M tets on two threads: refinement 1.04-1.16 s against
  // 1.08-1.28 s with all of the set-up on one thread. At 9.4 M tets the
  // set-ups still take 0.43 s of the rounds, against 0.53 s on one thread.)
  std::array<std::vector<ElementEntry>, 2> drained;
  parallel_tasks(2, threads_, [&](std::size_t l) {
    const int lane = static_cast<int>(l);
    LaneCellQueue& q = cells_.lane_queue(lane);
    while (!q.empty()) {
      const ElementEntry e = q.pop();
      if (complex_.is_live(e.stamp)) drained[l].push_back(e);
    }
    FacetLevel::Queue& f = facets_.lane_queue(lane);
    while (!f.empty()) {
      const ElementEntry e = f.top();
      f.pop();
      if (complex_.is_live(e.stamp)) drained[l].push_back(e);
    }
  });
  for (std::vector<ElementEntry>& d : drained) {
    entries.insert(entries.end(), d.begin(), d.end());
    d = {};
  }
  const int axis = axes_[rounds_ % static_cast<std::size_t>(cut_axes_)];
  std::vector<double> values(entries.size());
  parallel_for(entries.size(), threads_,
               [&](std::size_t i) { values[i] = coordinate(centre_of(entries[i]), axis); });
  cut_ = cut_at(tr_, axis, median(values));
  // Where each entry goes: a lane, or the sequential queues (-1).
  std::vector<std::int8_t> owner(entries.size());
  parallel_for(entries.size(), threads_, [&](std::size_t i) {
    const ElementEntry& e = entries[i];
    owner[i] = static_cast<std::int8_t>(is_facet(e) ? facets_.lane_of(e.cell, facet_index(e))
                                        : cut_.in_lane(e.cell, 0) ? 0
                                        : cut_.in_lane(e.cell, 1) ? 1
                                                                  : -1);
  });
  // Each lane's queues filled by one task, oldest first, so that each queue's
  // newest entries come out first, as before; the sequential ones by lane 0's.
  parallel_tasks(2, threads_, [&](std::size_t l) {
    const int lane = static_cast<int>(l);
    for (std::size_t i = entries.size(); i-- > 0;) {
      const ElementEntry& e = entries[i];
      if (owner[i] == lane) {
        if (is_facet(e))
          facets_.lane_queue(lane).push(e);
        else
          cells_.lane_queue(lane).push(CellLevel::bucket_of(e.priority), e);
      } else if (owner[i] < 0 && lane == 0) {
        if (is_facet(e))
          facets_.push(plain(e));
        else
          cells_.push(plain(e));
      }
    }
  });
  if (!pending()) return false;

  // 2. Both lanes at once, in steps: before each, on this thread, each lane's
  // pools get the vertices, cells and stamps of another `step`
  // insertions (the container grows by little more than the mesh needs);
  // a lane stops when they run low, or after its round quota.
  std::unique_ptr<Lane> lanes[2];
  for (int l = 0; l < 2; ++l) {
    lanes[l] = std::make_unique<Lane>(tr_, l, deadline);
    const std::size_t queued = facets_.lane_queue(l).size() + cells_.lane_queue(l).size();
    lanes[l]->quota = std::max(2 * queued, kMinQuota);
    lanes[l]->step = std::clamp(queued / kQueuedPerStep, kMinStep, kMaxStep);
  }
  std::vector<RestrictedComplex::StampBlock> blocks(2);
  for (;;) {
    ++stats.lane_steps;
    std::size_t step = 0;
    for (int l = 0; l < 2; ++l) {
      Lane& lane = *lanes[l];
      lane.step_quota = std::min(lane.step, lane.quota - lane.inserted);
      step = std::max(step, lane.step_quota);
    }
    complex_.reserve_stamp_blocks(static_cast<std::uint32_t>(step * kStampsPerInsertion + kSlack),
                                  blocks);
    for (int l = 0; l < 2; ++l) {
      Lane& lane = *lanes[l];
      lane.stamps = blocks[static_cast<std::size_t>(l)];
      lane.step_end = lane.inserted + lane.step_quota;
      lane.pool.fill(lane.step_quota * kCellsPerInsertion + kSlack);
      while (lane.vertices.size() < lane.step_quota)
        lane.vertices.push_back(tr_.tds().create_vertex());
      lane.full = false;
    }
    parallel_tasks(2, threads_, [&](std::size_t l) { run(*lanes[l]); });
    bool again = false, late = false, stopped = false;
    std::size_t most_left = 0;
    for (int l = 0; l < 2; ++l) {
      const Lane& lane = *lanes[l];
      const bool more = lane.full && lane.inserted < lane.quota;
      again = again || more;
      late = late || lane.out_of_time;
      if (more)
        most_left = std::max(most_left, facets_.lane_queue(l).size() + cells_.lane_queue(l).size());
      else
        stopped = true;
    }
    // Both lanes stop at the same step whatever the threads do (each stops on
    // its own queue and quota): the round's end depends on them alone.
    if (late || !again || (stopped && most_left >= kRebalance)) break;
  }

  // 3. What they did, lane by lane.
  bool out_of_time = false;
  for (int l = 0; l < 2; ++l) {
    Lane& lane = *lanes[l];
    stats.inserted_cell_centers += lane.inserted - lane.inserted_facets;
    stats.cell_centers_in_lanes += lane.inserted - lane.inserted_facets;
    stats.inserted_facet_centers += lane.inserted_facets;
    stats.facet_centers_in_lanes += lane.inserted_facets;
    for (const ElementEntry& e : lane.deferred) {
      if (!complex_.is_live(e.stamp)) continue;
      if (is_facet(e))
        facets_.push(plain(e));
      else
        cells_.push(plain(e));
    }
    for (const ElementEntry& e : lane.crossed)
      if (complex_.is_live(e.stamp)) crossed_.push_back(e);
    for (const Lane::FoundFacet& f : lane.facets)
      if (complex_.is_live(f.stamp)) facets_.consider(f.cell, f.facet);
    lane.pool.release();
    for (const Vertex_handle& v : lane.vertices) tr_.tds().delete_vertex(v);
    out_of_time = out_of_time || lane.out_of_time;
  }
  return out_of_time;
}

void RefinementLanes::run(Lane& lane) {
  LaneCellQueue& cells = cells_.lane_queue(lane.id);
  FacetLevel::Queue& facets = facets_.lane_queue(lane.id);
  while (!facets.empty() || !cells.empty()) {
    if (lane.deadline.passed(Deadline::kCheckEvery)) {
      lane.out_of_time = true;
      return;
    }
    if (lane.inserted == lane.step_end) {
      lane.full = true;
      return;
    }
    // The lane's facets first (R3, R4 before R5), as the sequential steps.
    ElementEntry e;
    if (!facets.empty()) {
      e = facets.top();
      facets.pop();
    } else {
      e = cells.pop();
    }
    switch (refine(lane, e)) {
      case Outcome::kDeferred:
        lane.deferred.push_back(e);
        break;
      case Outcome::kCrossed:
        // The next round cuts across another axis: most such zones are then
        // inside one lane. After kMaxCrossings, the sequential steps take it.
        if (crossings(e) >= kMaxCrossings)
          lane.deferred.push_back(e);
        else
          lane.crossed.push_back(as_crossed(e));
        break;
      case Outcome::kFull:
        if (is_facet(e))
          facets.push(e);
        else
          cells.push(CellLevel::bucket_of(e.priority), e);
        lane.full = true;
        return;
      case Outcome::kInserted:
      case Outcome::kDropped:
        break;
    }
  }
}

RefinementLanes::Outcome RefinementLanes::refine(Lane& lane, const ElementEntry& e) {
  const Cell_handle c = e.cell;
  if (!complex_.is_live(e.stamp)) return Outcome::kDropped;
  if (is_facet(e)) {
    const int i = facet_index(e);
    const Cell_handle n = c->neighbor(i);
    if (!cut_.in_lane(c, lane.id) || !cut_.in_lane(n, lane.id)) return Outcome::kDeferred;
    if (!facets_.violation(c, i)) return Outcome::kDropped;
    const Point3 center = c->info().surface_center[i];
    // The protecting balls' tests (CurveLevel::keeps_facet_centre) need the
    // sequential steps; a facet without weighted vertices has a positive ball.
    const double r2 = complex_.facet_power(c, i, center);
    if (!(r2 > 0)) return Outcome::kDeferred;
    // The centre lies on the facet's dual Voronoi edge: in the ball of one of
    // its two cells.
    const Weighted_point p = to_weighted(center);
    const Cell_handle start =
        tr_.side_of_power_sphere(c, p, /*perturb=*/true) == CGAL::ON_BOUNDED_SIDE ? c : n;
    const VertexInfo info{FeatureRef(c->info().facet_patch[i]), 0, -1};
    const Outcome done = insert(lane, center, r2, start, info);
    if (done == Outcome::kInserted) ++lane.inserted_facets;
    return done;
  }
  if (!cut_.in_lane(c, lane.id)) return Outcome::kDeferred;
  if (!cells_.violation(c)) return Outcome::kDropped;
  if (curves_.keeps_cell_centre(c)) return Outcome::kDropped;
  return insert(lane, c->info().circumcenter, c->info().squared_radius, c, VertexInfo{});
}

RefinementLanes::Outcome RefinementLanes::insert(Lane& lane, const Point3& center,
                                                 double squared_radius, Cell_handle start,
                                                 const VertexInfo& info) {
  // A ball across the cut: its zone nearly always crosses too, and finding
  // that out costs a walk. The next round's cut is across another axis.
  const double to_cut = coordinate(center, cut_.axis) - cut_.split;
  if (to_cut * to_cut < kBallReach * kBallReach * squared_radius) return Outcome::kCrossed;
  const Weighted_point p = to_weighted(center);
  const Vertex_handle infinite = tr_.infinite_vertex();
  // The lane's own cells without features: the curve level has nothing to see
  // in the zone (no arc's ball holds a point whose zone has no curve vertex),
  // and nothing outside the lane is read or written. (Infinite cells are a
  // lane's when the infinite vertex holds every lane, see cut_at:
  // then its cell() is one that neither lane owns.)
  auto owned = [&](Cell_handle x) {
    if (!cut_.in_lane(x, lane.id)) return false;
    for (int k = 0; k < 4; ++k) {
      const Vertex_handle w = x->vertex(k);
      if (w->info().dim() <= FeatureDim::kCurve || w->point().weight() != 0) return false;
    }
    return true;
  };
  if (!lane.walk.zone_if(tr_, p, start, lane.zone, lane.boundary, owned)) return Outcome::kCrossed;
  if (lane.zone.empty()) return Outcome::kDeferred;
  // refine-tet-facet-or-edge: an encroached facet is refined first (sequentially).
  if (info.dim() == FeatureDim::kVolume) {
    Cell_handle fc;
    int fi = -1;
    if (facets_.encroached(center, lane.zone, fc, fi)) return Outcome::kDeferred;
  }
  // The minimum-size guard: the sequential steps refuse and record it.
  for (const Cell_handle& z : lane.zone) {
    for (int k = 0; k < 4; ++k) {
      if (z->vertex(k) != infinite &&
          squared_norm(to_point3(z->vertex(k)->point()) - center) < min_size_sq_) {
        return Outcome::kDeferred;
      }
    }
  }
  const std::size_t extra =
      lane.boundary.size() > lane.zone.size() ? lane.boundary.size() - lane.zone.size() : 0;
  if (extra > lane.pool.size() || lane.boundary.size() > lane.stamps.left() ||
      lane.vertices.empty())
    return Outcome::kFull;

  for (const Cell_handle& z : lane.zone) complex_.kill_in_lane(z->info());
  const Vertex_handle v = lane.vertices.back();
  lane.vertices.pop_back();
  v->set_point(p);
  v->info() = info;
  lane.hole.clear();
  for (const Triangulation::Facet& f : lane.boundary) lane.hole.push_back({f.first, f.second});
  lane.cone.build(tr_, lane.zone, lane.hole, v, &lane.pool, lane.created);

  // As Refiner::inserted: labels, D|S around the star, the new bad elements.
  const std::uint32_t first_new = lane.stamps.next;
  for (const Cell_handle& n : lane.created)
    complex_.init_cell_in_lane(n, n->neighbor(n->index(v)), lane.stamps);
  FacetLevel::Queue& facets = facets_.lane_queue(lane.id);
  for (const Cell_handle& n : lane.created) {
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t ns = n->neighbor(i)->info().stamp;
      if ((ns < first_new || ns > n->info().stamp) && complex_.update_facet(n, i)) {
        // Both cells are the lane's (the zone's neighbours passed `owned`):
        // a bad facet with a small ball stays in the lane.
        const Violation bad = facets_.violation(n, i);
        if (bad && facets_.lane_of(n, i) == lane.id)
          facets.push({bad.priority, n, n->info().stamp, i});
        else if (bad)
          lane.facets.push_back({n, i, n->info().stamp});
      }
    }
  }
  LaneCellQueue& queue = cells_.lane_queue(lane.id);
  for (const Cell_handle& n : lane.created) {
    const Violation bad = cells_.violation(n);
    if (bad) queue.push(CellLevel::bucket_of(bad.priority), CellLevel::entry(n, bad));
  }
  ++lane.inserted;
  return Outcome::kInserted;
}

}  // namespace rdmesh::detail
