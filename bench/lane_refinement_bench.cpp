// rdmesh_lane_bench: can Delaunay refinement run on two threads, with the same
// result on any number of threads? A design measurement for issue 19 (two
// threads >= 1.7x one, byte-identical output), on the kernel that dominates a
// run: inserting circumcenters of cells too large for a uniform size into a
// regular triangulation (CGAL Epick, weights 0, as rdmesh's D(P)), LIFO.
//
// Spatial lanes: lane 0 owns the cells whose four vertices have x < 0.5, lane
// 1 those with x >= 0.5. A lane refines its own cells only, and only when the
// conflict zone and every cell next to it are its own; anything else waits for
// a sequential pass between rounds. A lane then reads and writes nothing the
// other lane writes, so what it does depends on the triangulation at the start
// of the round alone: the result is the same whether the lanes run one after
// the other or side by side (the checksum column says it is).
//
// What stays shared is where CGAL puts new cells and vertices: one container
// per kind, with one free list. Variants compared, in one run:
//   sequential     Sequential_tag, the plain LIFO loop (the reference);
//   lanes-parallel Parallel_tag: CGAL's concurrent container, a free list per thread;
//   lanes-slots    Sequential_tag, but each lane takes its cells and vertices from a
//                  list of slots handed to it before the round, in lane order (a
//                  specialization of CGAL::Compact_container for these cell and
//                  vertex types), and puts back what it erases: the lanes never
//                  share a cache line, and where every cell lives depends on the
//                  lanes' work alone, never on the timing of the threads;
//   halves         two separate triangulations of x < 0.5 and x >= 0.5 (not one
//                  mesh: what two threads give when they share no memory at all).
// Every variant runs with 1 and 2 threads, each run in a child process of its
// own. Times: the refinement loop only (best of --repeat), not building the
// initial 3000 random points.
#define CGAL_LINKED_WITH_TBB 1
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

/// Per cell: a generation (0 or 1: dead; a lane's live cells have gen % 4 ==
/// lane + 2, the sequential pass's gen % 4 == 1), the circumcenter and squared radius.
struct CellData {
  std::uint64_t gen = 0;
  double r2 = 0;
  double c[3] = {0, 0, 0};
};
/// Marks the vertex type, so that the container specialization below finds it.
struct VertexData {};

/// Where the lane running on this thread takes its slots from (null: the container's own).
template <class T>
inline thread_local std::vector<T*>* lane_slots = nullptr;

/// CGAL::Compact_container with lane slots: emplace() and erase() use the
/// calling thread's lane_slots<T> when it has one. The slots are constructed
/// and destroyed in place; the base container counts them as used meanwhile
/// (nothing iterates over the cells during a round).
template <class T, class Base>
struct LaneSlots : Base {
  using Base::Base;
  using iterator = typename Base::iterator;
  template <class... Args>
  iterator emplace(const Args&... args) {
    if (std::vector<T*>* slots = lane_slots<T>) {
      T* p = slots->back();
      slots->pop_back();
      new (p) T(args...);
      return Base::s_iterator_to(*p);
    }
    return Base::emplace(args...);
  }
  void erase(iterator x) {
    if (std::vector<T*>* slots = lane_slots<T>) {
      T* p = &*x;
      p->~T();
      slots->push_back(p);
      return;
    }
    Base::erase(x);
  }
  /// Tops `slots` up to `n` slots from the container (sequentially).
  void hand_out(std::vector<T*>& slots, std::size_t n) {
    while (slots.size() < n) {
      T* p = &*Base::emplace();
      p->~T();
      slots.push_back(p);
    }
  }
  /// Gives the slots back to the container.
  void take_back(std::vector<T*>& slots) {
    for (T* p : slots) {
      new (p) T();
      Base::erase(Base::s_iterator_to(*p));
    }
    slots.clear();
  }
};

/// LaneSlots over the ordinary Compact_container of T (its allocator named, so
/// that it is not one of the specializations below).
template <class T>
using LaneContainer =
    LaneSlots<T, CGAL::Compact_container<T, std::allocator<T>, CGAL::Default, CGAL::Default>>;

}  // namespace

namespace CGAL {
// The containers the triangulation data structure picks for these cells and
// vertices (Compact_container<T> with default arguments) get lane slots.
template <class Gt, class Cb>
class Compact_container<Triangulation_cell_base_with_info_3<CellData, Gt, Cb>, Default, Default,
                        Default>
    : public LaneContainer<Triangulation_cell_base_with_info_3<CellData, Gt, Cb>> {
  using Base = LaneContainer<Triangulation_cell_base_with_info_3<CellData, Gt, Cb>>;

 public:
  using Base::Base;
};
template <class Gt, class Vb>
class Compact_container<Triangulation_vertex_base_with_info_3<VertexData, Gt, Vb>, Default, Default,
                        Default>
    : public LaneContainer<Triangulation_vertex_base_with_info_3<VertexData, Gt, Vb>> {
  using Base = LaneContainer<Triangulation_vertex_base_with_info_3<VertexData, Gt, Vb>>;

 public:
  using Base::Base;
};
}  // namespace CGAL

namespace {

/// --check: verify every triangulation (CGAL's is_valid) after its refinement.
bool check_triangulation = false;

/// Slots handed to each lane per round (--slots): cells, and vertices (a sixth of it).
std::size_t lane_cells = 100000;

struct Outcome {
  double seconds = 0;
  std::size_t vertices = 0;
  double checksum = 0;         ///< over the vertices' coordinates: the same mesh, the same sum
  std::size_t sequential = 0;  ///< insertions left to the sequential passes
};

template <class Tag>
class Refinement {
 public:
  using Vb =
      CGAL::Triangulation_vertex_base_with_info_3<VertexData, K,
                                                  CGAL::Regular_triangulation_vertex_base_3<K>>;
  using Cb = CGAL::Triangulation_cell_base_with_info_3<
      CellData, K,
      CGAL::Regular_triangulation_cell_base_3<K, CGAL::Triangulation_cell_base_3<K>,
                                              CGAL::Discard_hidden_points>>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb, Tag>;
  using Tr = CGAL::Regular_triangulation_3<K, Tds>;
  using Cell_handle = typename Tr::Cell_handle;
  using Vertex_handle = typename Tr::Vertex_handle;
  using Facet = typename Tr::Facet;
  using Point = typename Tr::Weighted_point;
  static constexpr bool kSlots = std::is_same_v<Tag, CGAL::Sequential_tag>;

  /// Refines the cells of [x0, x1) x [0, 1)^2 to circumradius <= h.
  Refinement(double h, double x0, double x1) : h2_(h * h), x0_(x0), x1_(x1) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    for (int k = 0; k < 8; ++k)  // far corners: no infinite cell is ever in conflict
      tr_.insert(Point(K::Point_3(k & 1 ? 5 : -4, k & 2 ? 5 : -4, k & 4 ? 5 : -4), 0));
    for (int i = 0; i < 3000; ++i) {
      const double x = u(rng), y = u(rng), z = u(rng);
      if (x >= x0_ && x < x1_) tr_.insert(Point(K::Point_3(x, y, z), 0));
    }
  }

  /// The plain LIFO loop.
  Outcome sequential() {
    Lane all{-1, 1};
    for (auto c = tr_.all_cells_begin(); c != tr_.all_cells_end(); ++c) init_cell(all, c);
    const auto t0 = std::chrono::steady_clock::now();
    for (auto c = tr_.finite_cells_begin(); c != tr_.finite_cells_end(); ++c)
      if (bad(c)) all.queue.push_back({c, c->info().gen});
    drain(all, nullptr, all.queue);
    return finish(t0, all.inserted);
  }

  /// Rounds of two lanes (one after the other, or side by side), each followed
  /// by a sequential pass over what the lanes left.
  Outcome lanes(int threads) {
    Lane seam{-1, 1}, l0{0, 2}, l1{1, 3};
    Lane* lanes[2] = {&l0, &l1};
    for (auto c = tr_.all_cells_begin(); c != tr_.all_cells_end(); ++c) init_cell(seam, c);
    const auto t0 = std::chrono::steady_clock::now();
    for (auto c = tr_.finite_cells_begin(); c != tr_.finite_cells_end(); ++c)
      if (bad(c)) route(seam, lanes, c);
    for (;;) {
      if constexpr (kSlots) {
        for (Lane* l : lanes) {
          tr_.tds().cells().hand_out(l->cell_slots, lane_cells);
          tr_.tds().vertices().hand_out(l->vertex_slots, lane_cells / 6);
        }
      }
      if (threads > 1) {
        std::thread other([&] { run_lane(l1, lanes); });
        run_lane(l0, lanes);
        other.join();
      } else {
        run_lane(l0, lanes);
        run_lane(l1, lanes);
      }
      // What the lanes left, then what that made outside both lanes.
      std::vector<Entry> left;
      for (Lane* l : lanes) {
        left.insert(left.end(), l->deferred.begin(), l->deferred.end());
        l->deferred.clear();
      }
      drain(seam, lanes, left);
      if (l0.queue.empty() && l1.queue.empty() && seam.queue.empty()) break;
      left.swap(seam.queue);
      drain(seam, lanes, left);
    }
    if constexpr (kSlots) {
      for (Lane* l : lanes) {
        tr_.tds().cells().take_back(l->cell_slots);
        tr_.tds().vertices().take_back(l->vertex_slots);
      }
    }
    return finish(t0, seam.inserted);
  }

  /// --check: CGAL's validity test of the triangulation (outside the timings).
  void check() const {
    if (check_triangulation && !tr_.is_valid()) {
      std::fprintf(stderr, "invalid triangulation\n");
      std::exit(1);
    }
  }

 private:
  struct Entry {
    Cell_handle cell;
    std::uint64_t gen;
  };
  struct Lane {
    Lane(int lane_id, std::uint64_t first) : id(lane_id), next(first) {}
    int id;              ///< 0 or 1; -1: owns every finite cell (sequential)
    std::uint64_t next;  ///< the next generation it gives
    std::vector<Entry> queue, deferred;
    std::vector<Cell_handle> zone, stack, star, outside;
    std::vector<Facet> boundary;
    std::vector<typename Tds::Cell*> cell_slots;
    std::vector<typename Tds::Vertex*> vertex_slots;
    std::size_t inserted = 0;
  };

  bool owned(const Lane& lane, Cell_handle c) const {
    if (tr_.is_infinite(c)) return false;
    if (lane.id < 0) return true;
    for (int k = 0; k < 4; ++k)
      if ((c->vertex(k)->point().x() < 0.5 ? 0 : 1) != lane.id) return false;
    return true;
  }
  void init_cell(Lane& lane, Cell_handle c) {
    CellData& d = c->info();
    d.gen = lane.next += 4;
    if (tr_.is_infinite(c)) return;
    const K::Point_3 p =
        K::Construct_circumcenter_3()(c->vertex(0)->point().point(), c->vertex(1)->point().point(),
                                      c->vertex(2)->point().point(), c->vertex(3)->point().point());
    d.c[0] = p.x();
    d.c[1] = p.y();
    d.c[2] = p.z();
    d.r2 = CGAL::squared_distance(p, c->vertex(0)->point().point());
  }
  bool bad(Cell_handle c) const {
    const CellData& d = c->info();
    return !tr_.is_infinite(c) && d.r2 > h2_ && d.c[0] > x0_ && d.c[0] < x1_ && d.c[1] > 0 &&
           d.c[1] < 1 && d.c[2] > 0 && d.c[2] < 1;
  }
  /// A new bad cell: to its lane (a lane keeps what it makes), else to the sequential pass.
  void route(Lane& from, Lane* const* lanes, Cell_handle c) {
    Lane* to = &from;
    if (from.id < 0 && lanes != nullptr)
      for (int k = 0; k < 2; ++k)
        if (owned(*lanes[k], c)) to = lanes[k];
    to->queue.push_back({c, c->info().gen});
  }

  /// The conflict zone of p from `start` and its boundary, marked in the cells
  /// (tds_data) as CGAL's own walk does; false when a cell of the zone or next
  /// to it is not the lane's (nothing is inserted then).
  bool find_zone(Lane& lane, const Point& p, Cell_handle start) {
    lane.zone.clear();
    lane.boundary.clear();
    lane.outside.clear();
    if (!owned(lane, start)) return false;
    bool ok = true;
    lane.stack.assign(1, start);
    start->tds_data().mark_in_conflict();
    lane.zone.push_back(start);
    while (ok && !lane.stack.empty()) {
      const Cell_handle c = lane.stack.back();
      lane.stack.pop_back();
      for (int i = 0; i < 4 && ok; ++i) {
        const Cell_handle n = c->neighbor(i);
        if (n->tds_data().is_in_conflict()) continue;
        if (!owned(lane, n)) {
          ok = false;
        } else if (n->tds_data().is_clear() &&
                   tr_.side_of_power_sphere(n, p, true) == CGAL::ON_BOUNDED_SIDE) {
          n->tds_data().mark_in_conflict();
          lane.zone.push_back(n);
          lane.stack.push_back(n);
        } else {
          if (n->tds_data().is_clear()) {
            n->tds_data().mark_on_boundary();
            lane.outside.push_back(n);
          }
          lane.boundary.emplace_back(c, i);
        }
      }
    }
    for (const Cell_handle& c : lane.outside) c->tds_data().clear();
    if (!ok)
      for (const Cell_handle& c : lane.zone) c->tds_data().clear();
    return ok;  // the zone stays marked in conflict, as insert_in_hole wants it
  }

  /// Refines the cells of `queue` (LIFO) and what they make; entries whose zone
  /// leaves the lane go to its deferred list. A lane out of slots stops with the
  /// entry back on `queue`, for the next round.
  void drain(Lane& lane, Lane* const* lanes, std::vector<Entry>& queue) {
    while (!queue.empty()) {
      const Entry e = queue.back();
      queue.pop_back();
      if (e.cell->info().gen != e.gen) continue;  // destroyed since
      const CellData& d = e.cell->info();
      const Point p(K::Point_3(d.c[0], d.c[1], d.c[2]), 0);
      if (!find_zone(lane, p, e.cell)) {
        lane.deferred.push_back(e);
        continue;
      }
      if (kSlots && lane.id >= 0 &&
          (lane.vertex_slots.empty() || lane.cell_slots.size() < lane.boundary.size())) {
        // Out of slots: the lane's round ends here (the same point on any number of threads).
        for (const Cell_handle& c : lane.zone) c->tds_data().clear();
        queue.push_back(e);
        return;
      }
      for (const Cell_handle& c : lane.zone) c->info().gen = 1;
      const Facet& f = lane.boundary.front();
      // The data structure's own insertion: Regular_triangulation_3's keeps
      // shared scratch for hidden points (none here: every weight is 0).
      const Vertex_handle v =
          tr_.tds().insert_in_hole(lane.zone.begin(), lane.zone.end(), f.first, f.second);
      v->set_point(p);
      ++lane.inserted;
      lane.star.clear();
      tr_.incident_cells(v, std::back_inserter(lane.star));
      for (const Cell_handle& c : lane.star) init_cell(lane, c);
      for (const Cell_handle& c : lane.star)
        if (bad(c)) route(lane, lanes, c);
    }
  }
  void run_lane(Lane& lane, Lane* const* lanes) {
    if constexpr (kSlots) {
      lane_slots<typename Tds::Cell> = &lane.cell_slots;
      lane_slots<typename Tds::Vertex> = &lane.vertex_slots;
    }
    drain(lane, lanes, lane.queue);
    if constexpr (kSlots) {
      lane_slots<typename Tds::Cell> = nullptr;
      lane_slots<typename Tds::Vertex> = nullptr;
    }
  }

  Outcome finish(std::chrono::steady_clock::time_point t0, std::size_t sequential) const {
    Outcome o;
    o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    o.vertices = tr_.number_of_vertices();
    for (auto v = tr_.finite_vertices_begin(); v != tr_.finite_vertices_end(); ++v)
      o.checksum += v->point().x() + 2 * v->point().y() + 3 * v->point().z();
    o.sequential = sequential;
    return o;
  }

  Tr tr_;
  double h2_, x0_, x1_;
};

/// The cube refined sequentially or in lanes, on a triangulation with the Tag's containers.
template <class Tag>
Outcome refine_cube(double h, bool lanes, int threads) {
  Refinement<Tag> r(h, 0, 1);
  const Outcome o = lanes ? r.lanes(threads) : r.sequential();
  r.check();
  return o;
}

Outcome run(const std::string& variant, int threads, double h) {
  if (variant == "sequential") return refine_cube<CGAL::Sequential_tag>(h, false, 1);
  if (variant == "lanes-parallel") return refine_cube<CGAL::Parallel_tag>(h, true, threads);
  if (variant == "lanes-slots") return refine_cube<CGAL::Sequential_tag>(h, true, threads);
  // Two triangulations, built first, refined one after the other or side by side.
  Refinement<CGAL::Sequential_tag> a(h, 0, 0.5), b(h, 0.5, 1);
  Outcome oa, ob;
  const auto t0 = std::chrono::steady_clock::now();
  if (threads > 1) {
    std::thread other([&] { ob = b.sequential(); });
    oa = a.sequential();
    other.join();
  } else {
    oa = a.sequential();
    ob = b.sequential();
  }
  oa.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  oa.vertices += ob.vertices;
  oa.checksum += ob.checksum;
  a.check();
  b.check();
  return oa;
}

/// run() in a child process: every run starts from a fresh heap (a run that
/// reused the pages an earlier one freed and faulted in would look faster).
Outcome run_in_child(const std::string& variant, int threads, double h) {
  int fds[2];
  if (pipe(fds) != 0) std::exit(1);
  const pid_t pid = fork();
  if (pid < 0) std::exit(1);
  if (pid == 0) {
    close(fds[0]);
    const Outcome o = run(variant, threads, h);
    const bool written = write(fds[1], &o, sizeof o) == static_cast<ssize_t>(sizeof o);
    std::_Exit(written ? 0 : 1);
  }
  close(fds[1]);
  Outcome o;
  const bool read_all = read(fds[0], &o, sizeof o) == static_cast<ssize_t>(sizeof o);
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!read_all || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "%s with %d threads failed\n", variant.c_str(), threads);
    std::exit(1);
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  double h = 0.01;
  int repeat = 1;
  for (int i = 1; i < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--check") {
      check_triangulation = true;
      --i;
    } else if (i + 1 == argc) {
      std::fprintf(stderr, "usage: %s [--size H] [--repeat N] [--slots CELLS] [--check]\n",
                   argv[0]);
      return 2;
    } else if (a == "--slots") {
      lane_cells = static_cast<std::size_t>(std::max(1000, std::atoi(argv[i + 1])));
    } else if (a == "--size") {
      h = std::atof(argv[i + 1]);
    } else if (a == "--repeat") {
      repeat = std::max(1, std::atoi(argv[i + 1]));
    } else {
      std::fprintf(stderr, "usage: %s [--size H] [--repeat N] [--slots CELLS] [--check]\n",
                   argv[0]);
      return 2;
    }
  }
  std::printf(
      "| variant | threads | refine s | / sequential | vertices | checksum | sequential-pass "
      "insertions |\n");
  std::printf("|---|---:|---:|---:|---:|---|---:|\n");
  double reference = 0;
  for (const char* variant : {"sequential", "lanes-parallel", "lanes-slots", "halves"}) {
    for (int threads = 1; threads <= (std::string(variant) == "sequential" ? 1 : 2); ++threads) {
      Outcome best;
      for (int r = 0; r < repeat; ++r) {
        const Outcome o = run_in_child(variant, threads, h);
        if (r == 0 || o.seconds < best.seconds) best = o;
      }
      if (reference == 0) reference = best.seconds;
      std::printf("| %s | %d | %.2f | %.2f | %zu | %.10g | %zu |\n", variant, threads, best.seconds,
                  best.seconds / reference, best.vertices, best.checksum, best.sequential);
      std::fflush(stdout);
    }
  }
  return 0;
}
