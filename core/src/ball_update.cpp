// Refiner::update_balls: after the planner shrank some protecting balls, move
// only the balls that changed instead of building the triangulation again.
// A restart used to repeat all of insert_initial_points (inserting every ball
// and patch point, labeling every cell, asking the oracle about every facet);
// between two plans 80-98% of the balls are the same, and the cells away from
// the changed ones keep their labels and facets.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "rdmesh/errors.h"
#include "refiner.h"

namespace rdmesh::detail {
namespace {

// A ball's identity: its centre, radius and feature, bit for bit.
struct BallKey {
  double x, y, z, w, t;
  int dim, feature;
  bool operator==(const BallKey& o) const {
    return std::memcmp(this, &o, sizeof(BallKey)) == 0;
  }
};

struct BallKeyHash {
  std::size_t operator()(const BallKey& k) const {
    std::size_t h = 1469598103934665603ull;
    const unsigned char* p = reinterpret_cast<const unsigned char*>(&k);
    for (std::size_t i = 0; i < sizeof(BallKey); ++i) h = (h ^ p[i]) * 1099511628211ull;
    return h;
  }
};

BallKey key_of(const Point3& p, double weight, FeatureDim dim, int feature, double t) {
  BallKey k;
  std::memset(&k, 0, sizeof k);  // padding too: keys are compared bytewise
  k.x = p.x, k.y = p.y, k.z = p.z, k.w = weight, k.t = dim == FeatureDim::kCurve ? t : 0;
  k.dim = static_cast<int>(dim), k.feature = feature;
  return k;
}

// The balls that appeared or went, sorted by x, to find the patch points they hold.
class ChangedBalls {
 public:
  void add(const Point3& c, double r) {
    balls_.push_back({c, r});
    reach_ = std::max(reach_, r);
  }
  void sort() {
    std::sort(balls_.begin(), balls_.end(),
              [](const Ball& a, const Ball& b) { return a.c.x < b.c.x; });
  }
  bool empty() const { return balls_.empty(); }
  /// Whether p lies in (or on) one of the balls.
  bool hold(const Point3& p) const {
    auto it = std::lower_bound(balls_.begin(), balls_.end(), p.x - reach_,
                               [](const Ball& b, double x) { return b.c.x < x; });
    for (; it != balls_.end() && it->c.x <= p.x + reach_; ++it) {
      if (squared_norm(p - it->c) <= it->r * it->r) return true;
    }
    return false;
  }

 private:
  struct Ball {
    Point3 c;
    double r;
  };
  std::vector<Ball> balls_;
  double reach_ = 0;
};

// The largest share of the vertices whose removal update_balls() takes on
// (measured on five CAD parts: 0.07-0.2 ms per removed ball, 0.02 ms per
// vertex for a fresh build).
constexpr double kMostGone = 0.125;

}  // namespace

bool Refiner::update_balls() {
  if (!plan_ || !stopped_at_check_) return false;
  std::vector<std::size_t> first_ball;
  const std::vector<PlannedBall> balls = planned_balls(first_ball);

  // The ball vertices there now, by identity.
  std::unordered_map<BallKey, Vertex_handle, BallKeyHash> present;
  for (auto v = tr_.finite_vertices_begin(); v != tr_.finite_vertices_end(); ++v) {
    const VertexInfo& i = v->info();
    if (i.ball_weight > 0) {
      present.emplace(key_of(to_point3(v->point()), v->point().weight(), i.dim, i.feature, i.t),
                      v);
    }
  }
  std::vector<Vertex_handle> vertex(balls.size());
  std::vector<std::size_t> added;
  ChangedBalls changed;
  for (std::size_t k = 0; k < balls.size(); ++k) {
    const PlannedBall& b = balls[k];
    const auto it = present.find(key_of(b.point, b.radius * b.radius, b.dim, b.feature, b.t));
    if (it != present.end()) {
      vertex[k] = it->second;
      present.erase(it);
    } else {
      added.push_back(k);
      changed.add(b.point, b.radius);
    }
  }
  // What is left in `present` is not in the plan any more. Removing a vertex
  // costs as much as inserting 5-10 (CGAL builds a triangulation of its link):
  // beyond kMostGone of the vertices, building afresh is faster.
  if (static_cast<double>(present.size()) > kMostGone * tr_.number_of_vertices()) return false;
  stopped_at_check_ = false;
  conflicts_.clear();
  std::vector<Vertex_handle> gone;
  for (const auto& [key, v] : present) gone.push_back(v);
  std::sort(gone.begin(), gone.end(), [](Vertex_handle a, Vertex_handle b) {
    return a->point().x() < b->point().x() ||
           (a->point().x() == b->point().x() && a->point().y() < b->point().y()) ||
           (a->point().x() == b->point().x() && a->point().y() == b->point().y() &&
            a->point().z() < b->point().z());
  });  // a fixed order: the hash map's is not
  for (const Vertex_handle& v : gone) {
    changed.add(to_point3(v->point()), std::sqrt(v->point().weight()));
    tr_.remove(v);
  }
  stats_.initial_points = stats_.initial_points + added.size() - gone.size();
  insert_balls(balls, std::move(added), vertex);
  bind_curve_samples(vertex, first_ball);

  // Patch points: those in a ball that went may now be inserted, those in a
  // ball that came must go (a vertex inside a ball would break the protection).
  changed.sort();
  if (!changed.empty()) {
    Cell_handle hint;
    for (const PatchInfo& patch : oracle_.patches()) {
      for (const Point3& p : oracle_.initial_points(patch.id)) {
        if (!changed.hold(p)) continue;
        Triangulation::Locate_type lt;
        int li = 0, lj = 0;
        const Cell_handle c = tr_.locate(to_weighted(p), lt, li, lj, hint);
        hint = c;
        if (lt == Triangulation::VERTEX) {
          const Vertex_handle v = c->vertex(li);
          if (v->info().dim == FeatureDim::kPatch && !outside_balls(p, c)) {
            tr_.remove(v);
            --stats_.initial_points;
            hint = Cell_handle();
          }
          continue;
        }
        insert_patch_point(p, patch.id.value, hint);
      }
    }
  }
  std::size_t ball_vertices = 0;
  for (auto v = tr_.finite_vertices_begin(); v != tr_.finite_vertices_end(); ++v) {
    ball_vertices += v->info().ball_weight > 0;
  }
  if (ball_vertices != balls.size()) {
    throw InternalError("protecting balls hide one another (" + std::to_string(balls.size()) +
                        " planned, " + std::to_string(ball_vertices) + " in the triangulation)");
  }

  // The queues again: the old cells' entries (some of their cells are gone),
  // then the new cells' through init_new_cells().
  facet_queue_ = {};
  cell_queue_ = {};
  for (auto c = tr_.all_cells_begin(); c != tr_.all_cells_end(); ++c) {
    const std::uint32_t stamp = c->info().stamp;
    if (stamp == 0) continue;
    for (int i = 0; i < 4; ++i) {
      if (c->neighbor(i)->info().stamp <= stamp) continue;  // new (0), or seen from there
      const double badness = facet_badness(c, i);
      if (badness > 0) facet_queue_.push({badness, stamp, c, i});
    }
    const double badness = cell_badness(c);
    if (badness > 0) cell_queue_.push({badness, stamp, c, -1});
  }
  init_new_cells();
  return true;
}

}  // namespace rdmesh::detail
