// The protecting balls of [CDR07] as the curve level (RR-7912's conclusion):
// the plan's balls go into the triangulation as weighted points before any
// patch point, and their chains are D|L already, so this level never refines.
// It keeps refinement points out of the balls, and finds the balls that reach
// a patch their feature does not bound (R3 cannot be met there until they
// shrink: generate_mesh() shrinks them and starts again).
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "level_curves.h"
#include "level_facets.h"
#include "rdmesh/errors.h"
#include "rdmesh/number_text.h"

namespace rdmesh::detail {

namespace {
/// A ball reaches a facet's patch when the facet's surface centre lies within
/// sqrt(kConflictReach) radii of its centre (a squared factor on the weight).
constexpr double kConflictReach = 1.5;
/// Two overlapping unrelated balls shrink at once to this fraction of the
/// distance that would make them disjoint, and at least by half.
constexpr double kDisjointMargin = 0.95;
constexpr double kMaxShrinkFactor = 0.5;
/// The surface is looked for this many facet distances on each side of a
/// facet joining overlapping balls.
constexpr double kSurfaceSearchReach = 1.5;
}  // namespace

ProtectingBallsLevel::ProtectingBallsLevel(const ProtectionPlan& plan, RestrictedCurves& curves,
                                           RestrictedComplex& complex, const DomainOracle& oracle,
                                           const Criteria& criteria)
    : plan_(plan),
      curves_(curves),
      complex_(complex),
      tr_(complex.triangulation()),
      oracle_(oracle),
      criteria_(criteria) {}

namespace {

struct Ball {
  Point3 point;
  double radius;
  FeatureRef feature;
  double t;
};

/// Every ball once: a corner's ball for all its curves, a closed curve's first
/// sample for its repeated last one. first_ball[j]: the index of curve j's
/// own first ball.
std::vector<Ball> gather_balls(const ProtectionPlan& plan, const std::vector<CornerInfo>& corners,
                               const std::vector<CurveState>& curves,
                               std::vector<std::size_t>& first_ball) {
  std::vector<Ball> balls;
  for (std::size_t q = 0; q < corners.size(); ++q) {
    balls.push_back({corners[q].point, plan.corner_radius[q],
                     FeatureRef(CornerId{static_cast<int>(q) + 1}), 0});
  }
  first_ball.assign(curves.size(), 0);
  for (std::size_t j = 0; j < curves.size(); ++j) {
    const std::vector<BallSample>& s = plan.curves[j].samples;
    first_ball[j] = balls.size();
    const std::size_t from = curves[j].info.closed ? 0 : 1;
    for (std::size_t i = from; i + 1 < s.size(); ++i) {
      balls.push_back(
          {s[i].point, s[i].radius, FeatureRef(CurveId{static_cast<int>(j) + 1}), s[i].t});
    }
  }
  return balls;
}

/// Inserts the balls as weighted points in spatial order: the walks from one
/// insertion to the next become short. The regular triangulation does not
/// depend on the order; the creation order of its cells, which refinement
/// follows on ties, does. Returns each ball's vertex; `shared` counts the
/// balls equal to an earlier one.
std::vector<Vertex_handle> insert_balls(Triangulation& tr, const std::vector<Ball>& balls,
                                        Deadline& deadline, std::size_t& shared) {
  std::vector<Kernel::Point_3> points;
  for (const Ball& b : balls) points.emplace_back(b.point.x, b.point.y, b.point.z);
  std::vector<std::size_t> order(balls.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  using SortTraits =
      CGAL::Spatial_sort_traits_adapter_3<Kernel,
                                          CGAL::Pointer_property_map<Kernel::Point_3>::type>;
  CGAL::spatial_sort(order.begin(), order.end(), SortTraits(CGAL::make_property_map(points)));

  std::vector<Vertex_handle> vertex(balls.size());
  shared = 0;
  Cell_handle hint;
  for (const std::size_t k : order) {
    deadline.check(Deadline::kCheckEvery);
    const Ball& b = balls[k];
    const Weighted_point wp(points[k], b.radius * b.radius);
    const Vertex_handle v = tr.insert(wp, hint);
    if (v != Vertex_handle() && v->info().dim() != FeatureDim::kVolume && v->point() == wp) {
      // Features closer than anything the planner can separate (edges of
      // touching solids left unmerged) share the vertex: the planner made
      // their balls equal, and the conflict is reported.
      vertex[k] = v;
      ++shared;
      continue;
    }
    if (v == Vertex_handle() || v->info().dim() != FeatureDim::kVolume) {
      throw InternalError("protecting ball at " + point_text(b.point) +
                          " is hidden by another or coincides with it");
    }
    v->info().feature = b.feature;
    v->info().t = b.t;
    v->info().ball_weight = b.radius * b.radius;
    hint = v->cell();
    vertex[k] = v;
  }
  return vertex;
}

}  // namespace

void ProtectingBallsLevel::insert_initial_points(Deadline& deadline, RefinementStats& stats) {
  std::vector<CurveState>& curves = curves_.curves();
  std::vector<std::size_t> first_ball;
  const std::vector<Ball> balls = gather_balls(plan_, curves_.corners(), curves, first_ball);
  std::size_t shared = 0;  // balls equal to an earlier one (coincident features)
  const std::vector<Vertex_handle> vertex = insert_balls(tr_, balls, deadline, shared);
  // Each curve's samples are its balls' vertices, ends included (D|L).
  for (std::size_t j = 0; j < curves.size(); ++j) {
    CurveState& c = curves[j];
    const std::vector<BallSample>& s = plan_.curves[j].samples;
    for (std::size_t i = 0; i < s.size(); ++i) {
      Vertex_handle v;
      if (c.info.closed) {
        v = vertex[first_ball[j] + (i + 1 == s.size() ? 0 : i)];
      } else if (i == 0) {
        v = vertex[c.info.start.value - 1];
      } else if (i + 1 == s.size()) {
        v = vertex[c.info.end.value - 1];
      } else {
        v = vertex[first_ball[j] + i - 1];
      }
      c.samples[s[i].t] = CurveSample{v, to_point3(v->point())};
    }
  }
  // A vertex hidden by a later ball would vanish from the triangulation.
  if (tr_.number_of_vertices() + shared != balls.size()) {
    throw InternalError("protecting balls hide one another (" + std::to_string(balls.size()) +
                        " inserted, " + std::to_string(tr_.number_of_vertices()) + " remain)");
  }
  stats.initial_points += balls.size() - shared;
}

bool ProtectingBallsLevel::keeps_out(const Point3& p, Cell_handle hint) const {
  if (tr_.number_of_vertices() == 0) return false;
  const Kernel::Point_3 x(p.x, p.y, p.z);
  const Vertex_handle v = tr_.nearest_power_vertex(x, hint);
  if (v == Vertex_handle()) return false;
  return !(squared_norm(p - to_point3(v->point())) - v->point().weight() > 0);
}

bool ProtectingBallsLevel::keeps_facet_centre(Cell_handle c, int i, const VertexInfo& info,
                                              Insertion& insertion) {
  const Point3 center = c->info().surface_center[i];
  // A ball reaching into a patch its feature does not bound: R3 cannot be
  // met there until the ball shrinks. Other facets whose surface ball has no
  // positive radius lie inside the balls: protected, not refined.
  if (ball_conflict(c, i) || !(complex_.facet_power(c, i, center) > 0)) return true;
  // The guard before the conflict zone: the facet's vertices are vertices
  // of every cell in conflict, so one closer than the minimum size refuses
  // the point as Insertion::insert would, without the zone's cost (most of
  // the run where features lie closer than the minimum size).
  for (int k = 1; k < 4; ++k) {
    const Vertex_handle v = c->vertex((i + k) & 3);
    if (insertion.too_close(center, v)) {
      insertion.record_guard(info, v->info());
      return true;
    }
  }
  return false;
}

bool ProtectingBallsLevel::find_early_conflicts(const FacetLevel& facets) {
  // The facets between the balls alone already show most balls that reach
  // a patch their feature does not bound (R3), and most overlaps that stray
  // from the surface: shrink them before any refinement work.
  for (auto c = tr_.finite_cells_begin(); c != tr_.finite_cells_end(); ++c) {
    for (int i = 0; i < 4; ++i) {
      if (c->info().facet_patch[i] != kNotRestricted &&
          c->neighbor(i)->info().stamp > c->info().stamp) {
        if (facets.violation(c, i).rule == Rule::kR3NotFaithful) ball_conflict(c, i);
        overlap_conflict(c, i);
      }
    }
  }
  return !conflicts_.empty();
}

bool ProtectingBallsLevel::ball_conflict(Cell_handle c, int i) {
  const PatchId patch = c->info().facet_patch[i];
  const Point3 center = c->info().surface_center[i];
  for (int k = 1; k < 4; ++k) {
    const Vertex_handle v = c->vertex((i + k) & 3);
    const double w = v->point().weight();
    if (w == 0 || complex_.on_patch(v->info(), patch)) continue;
    // The surface center is on the sphere of the facet's orthoball, so it lies
    // near or in this ball only when the ball reaches the patch (an early,
    // coarse facet far from the ball is refined as usual).
    if (squared_norm(center - to_point3(v->point())) > kConflictReach * w) continue;
    add_conflict(ball_of(v->info()));
    return true;
  }
  return false;
}

BallRef ProtectingBallsLevel::ball_of(const VertexInfo& info) const {
  if (info.dim() == FeatureDim::kCorner) return BallRef::at_corner(info.feature.corner().value - 1);
  const std::size_t curve = info.feature.curve().value - 1;
  const std::vector<BallSample>& s = plan_.curves[curve].samples;
  const auto it = std::lower_bound(s.begin(), s.end(), info.t,
                                   [](const BallSample& b, double t) { return b.t < t; });
  return BallRef::on_curve(curve, it - s.begin());
}

void ProtectingBallsLevel::add_conflict(const BallRef& ref) {
  for (BallRef& b : conflicts_) {
    if (b.same_ball(ref)) {
      b.factor = std::min(b.factor, ref.factor);
      return;
    }
  }
  conflicts_.push_back(ref);
}

void ProtectingBallsLevel::overlap_conflict(Cell_handle c, int i) {
  auto info_of = [&](int j) -> const CurveInfo& { return curves_.curves()[j].info; };
  // The overlapping pairs of unrelated balls among the facet's vertices (a
  // vector: it allocates only for a facet that has some).
  std::vector<BallRef> pairs;
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
      const double factor = std::min(kMaxShrinkFactor, kDisjointMargin * dist / need);
      for (const BallRef& ball : {ball_a, ball_b}) {
        pairs.push_back(ball);
        pairs.back().factor = factor;
      }
    }
  }
  if (pairs.empty()) return;
  // The surface within the facet distance of the centroid, along the normal.
  const Point3 p[3] = {to_point3(c->vertex((i + 1) & 3)->point()),
                       to_point3(c->vertex((i + 2) & 3)->point()),
                       to_point3(c->vertex((i + 3) & 3)->point())};
  const Point3 normal = cross(p[1] - p[0], p[2] - p[0]);
  const double len = norm(normal);
  if (!(len > 0)) return;
  const Point3 g = (1.0 / 3) * (p[0] + p[1] + p[2]);
  const Point3 reach = (kSurfaceSearchReach * criteria_.facet_distance(g) / len) * normal;
  if (oracle_.intersect(g - reach, g + reach)) return;
  for (const BallRef& ball : pairs) add_conflict(ball);
}

}  // namespace rdmesh::detail
