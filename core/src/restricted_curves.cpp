// D|L_j: the restricted Delaunay triangulations of the curves (RR-7912 section 3).
//
// Rules on an arc between consecutive samples p, q of curve L_j, with
// restricted Delaunay ball B(c, r) (c on the arc, |c - p| = |c - q| = r):
//   R1  a vertex not on the arc lies inside B: the edge pq is not in D|L_j
//       and the Voronoi cell of another vertex reaches the arc: refine-edge;
//   R2  r > edge_size(c), or the chord pq is farther than facet_distance from
//       c: refine-edge.
// refine-edge inserts c, on the true curve.
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <limits>

#include "rdmesh/errors.h"
#include "rdmesh/number_text.h"
#include "refiner.h"
#include "simplex_geometry.h"

namespace rdmesh::detail {

void Refiner::load_curves() {
  std::vector<std::vector<int>> corner_patches, curve_patches;  // for R3, by id - 1
  corners_ = oracle_.corners();
  for (std::size_t i = 0; i < corners_.size(); ++i) {
    if (corners_[i].id.value != static_cast<int>(i) + 1) {
      throw OracleError("oracle corners must have ids 1..n in order");
    }
    std::vector<int> patches;
    for (const PatchId& p : corners_[i].patches) patches.push_back(p.value);
    corner_patches.push_back(std::move(patches));
  }
  for (const CurveInfo& info : oracle_.curves()) {
    if (info.id.value != static_cast<int>(curves_.size()) + 1) {
      throw OracleError("oracle curves must have ids 1..n in order");
    }
    CurveState state;
    state.info = info;
    state.curve = &oracle_.curve(info.id);
    curves_.push_back(std::move(state));
    std::vector<int> patches;
    for (const PatchId& p : info.patches) patches.push_back(p.value);
    curve_patches.push_back(std::move(patches));
  }
  complex_.set_feature_patches(std::move(corner_patches), std::move(curve_patches));
}

void Refiner::insert_corners_and_curve_samples() {
  std::vector<Vertex_handle> corner_vertex(corners_.size());
  Cell_handle hint;
  auto insert = [&](const Point3& p, FeatureDim dim, int feature, double t) {
    const Vertex_handle v = tr_.insert(to_weighted(p), hint);
    if (v->info().dim != FeatureDim::kVolume && v->info().dim != dim) {
      throw OracleError("two features of the oracle share the point " + point_text(p));
    }
    v->info().dim = dim;
    v->info().feature = feature;
    v->info().t = t;
    hint = v->cell();
    ++stats_.initial_points;
    return v;
  };
  for (std::size_t i = 0; i < corners_.size(); ++i) {
    corner_vertex[i] = insert(corners_[i].point, FeatureDim::kCorner, static_cast<int>(i) + 1, 0);
  }
  // Each curve starts with its ends and two interior points (three arcs), so
  // that no arc is the whole of a closed curve.
  for (std::size_t j = 0; j < curves_.size(); ++j) {
    CurveState& c = curves_[j];
    const double tb = c.info.t_begin, te = c.info.t_end;
    const int id = static_cast<int>(j) + 1;
    const double total = c.curve->length(tb, te);
    Vertex_handle first;
    if (c.info.closed) {
      first = insert(c.curve->point(tb), FeatureDim::kCurve, id, tb);
    } else {
      first = corner_vertex.at(c.info.start.value - 1);
    }
    c.samples[tb] = CurveSample{first, to_point3(first->point())};
    for (int k = 1; k <= 2; ++k) {
      const double t = c.curve->parameter_at_length(tb, total * k / 3.0);
      if (t <= tb || t >= te) continue;
      const Vertex_handle v = insert(c.curve->point(t), FeatureDim::kCurve, id, t);
      c.samples[t] = CurveSample{v, to_point3(v->point())};
    }
    const Vertex_handle last = c.info.closed ? first : corner_vertex.at(c.info.end.value - 1);
    c.samples[te] = CurveSample{last, to_point3(last->point())};
  }
}

void Refiner::insert_protecting_balls() {
  // Every ball once (a corner's ball for all its curves, a closed curve's first
  // sample for its repeated last one), inserted in spatial order: the walks
  // from one insertion to the next become short. The regular triangulation
  // does not depend on the order; the creation order of its cells, which
  // refinement follows on ties, does.
  struct Ball {
    Point3 point;
    double radius;
    FeatureDim dim;
    int feature;
    double t;
  };
  std::vector<Ball> balls;
  for (std::size_t q = 0; q < corners_.size(); ++q) {
    balls.push_back({corners_[q].point, plan_->corner_radius[q], FeatureDim::kCorner,
                     static_cast<int>(q) + 1, 0});
  }
  std::vector<std::size_t> first_ball(curves_.size());  // of each curve's own balls
  for (std::size_t j = 0; j < curves_.size(); ++j) {
    const std::vector<BallSample>& s = plan_->curves[j].samples;
    first_ball[j] = balls.size();
    const std::size_t from = curves_[j].info.closed ? 0 : 1;
    for (std::size_t i = from; i + 1 < s.size(); ++i) {
      balls.push_back(
          {s[i].point, s[i].radius, FeatureDim::kCurve, static_cast<int>(j) + 1, s[i].t});
    }
  }
  std::vector<Kernel::Point_3> points;
  for (const Ball& b : balls) points.emplace_back(b.point.x, b.point.y, b.point.z);
  std::vector<std::size_t> order(balls.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  using SortTraits =
      CGAL::Spatial_sort_traits_adapter_3<Kernel,
                                          CGAL::Pointer_property_map<Kernel::Point_3>::type>;
  CGAL::spatial_sort(order.begin(), order.end(), SortTraits(CGAL::make_property_map(points)));

  std::vector<Vertex_handle> vertex(balls.size());
  std::size_t shared = 0;  // balls equal to an earlier one (coincident features)
  Cell_handle hint;
  for (const std::size_t k : order) {
    deadline_.check(256);
    const Ball& b = balls[k];
    const Weighted_point wp(points[k], b.radius * b.radius);
    const Vertex_handle v = tr_.insert(wp, hint);
    if (v != Vertex_handle() && v->info().dim != FeatureDim::kVolume && v->point() == wp) {
      // Features closer than anything the planner can separate (edges of
      // touching solids left unmerged) share the vertex: the planner made
      // their balls equal, and the conflict is reported.
      vertex[k] = v;
      ++shared;
      continue;
    }
    if (v == Vertex_handle() || v->info().dim != FeatureDim::kVolume) {
      throw InternalError("protecting ball at " + point_text(b.point) +
                          " is hidden by another or coincides with it");
    }
    v->info().dim = b.dim;
    v->info().feature = b.feature;
    v->info().t = b.t;
    v->info().ball_weight = b.radius * b.radius;
    hint = v->cell();
    vertex[k] = v;
  }
  for (std::size_t j = 0; j < curves_.size(); ++j) {
    CurveState& c = curves_[j];
    const std::vector<BallSample>& s = plan_->curves[j].samples;
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
  stats_.initial_points += balls.size() - shared;
}

ChainEdges Refiner::chain_edges() const {
  ChainEdges chains;
  for (const CurveState& c : curves_) {
    for (auto a = c.samples.begin(); std::next(a) != c.samples.end(); ++a) {
      chains.add(a->second.vertex, std::next(a)->second.vertex);
    }
  }
  chains.finish();
  return chains;
}

bool Refiner::outside_balls(const Point3& p, Cell_handle hint) const {
  if (tr_.number_of_vertices() == 0) return true;
  const Kernel::Point_3 x(p.x, p.y, p.z);
  const Vertex_handle v = tr_.nearest_power_vertex(x, hint);
  if (v == Vertex_handle()) return true;
  return squared_norm(p - to_point3(v->point())) - v->point().weight() > 0;
}

void Refiner::create_arc(int curve, CurveState::Arc a, bool check_empty) {
  CurveState& c = curves_[curve];
  const auto b = std::next(a);
  const Point3 p = to_point3(a->second.vertex->point());
  const Point3 q = to_point3(b->second.vertex->point());
  // The ball center: where the arc crosses the bisector plane of pq (the
  // largest ball if it crosses several times).
  const Point3 n = q - p;
  const double offset = 0.5 * (squared_norm(q) - squared_norm(p));
  double best_t = 0, best_r2 = -1;
  for (double t : c.curve->plane_crossings(n, offset, a->first, b->first)) {
    const double r2 = squared_norm(c.curve->point(t) - p);
    if (r2 > best_r2) best_t = t, best_r2 = r2;
  }
  if (best_r2 < 0) {  // numerically no crossing: take the arc's middle
    best_t = c.curve->parameter_at_length(a->first, 0.5 * c.curve->length(a->first, b->first));
  }
  CurveSample& s = a->second;
  s.t_center = best_t;
  s.center = c.curve->point(best_t);
  s.squared_radius = std::max(squared_norm(s.center - p), squared_norm(s.center - q));
  Violation violation = arc_violation(curve, a);
  if (check_empty) {
    // R1: is the ball empty? Its nearest vertex must be p or q.
    const Vertex_handle w = tr_.nearest_power_vertex(
        Kernel::Point_3(s.center.x, s.center.y, s.center.z), a->second.vertex->cell());
    if (w != a->second.vertex && w != b->second.vertex &&
        squared_norm(to_point3(w->point()) - s.center) < s.squared_radius) {
      violation = Violation::topological(Rule::kR1NotRestricted);
    }
  }
  if (violation) push_arc(curve, a, violation);
}

Violation Refiner::arc_violation(int curve, CurveState::Arc a) const {
  const CurveSample& s = a->second;
  const Point3 p = to_point3(s.vertex->point());
  const Point3 q = to_point3(std::next(a)->second.vertex->point());
  Violation worst;
  const double sigma = criteria_.edge_size(s.center);
  if (s.squared_radius > sigma * sigma) {
    worst.worsen(Rule::kR2Size, s.squared_radius / (sigma * sigma));
  }
  const double d2 = squared_distance_to_segment(s.center, p, q);
  const double dmax = criteria_.facet_distance(s.center), dmax2 = dmax * dmax;
  if (d2 > dmax2) worst.worsen(Rule::kR2Distance, d2 / dmax2);
  (void)curve;
  return worst;
}

void Refiner::push_arc(int curve, CurveState::Arc a, const Violation& violation) {
  arc_queue_.push({violation.priority, next_arc_order_++,
                   ArcRef{curve, a->first, a->second.vertex, std::next(a)->second.vertex},
                   violation.rule});
}

std::optional<CurveState::Arc> Refiner::find_arc(const ArcRef& ref) {
  CurveState& c = curves_[ref.curve];
  const auto a = c.samples.find(ref.t);
  if (a == c.samples.end() || !c.has_next(a)) return std::nullopt;
  if (a->second.vertex != ref.a || std::next(a)->second.vertex != ref.b) return std::nullopt;
  return a;
}

void Refiner::arcs_of(Vertex_handle v, std::vector<std::pair<int, CurveState::Arc>>& out) {
  out.clear();
  const VertexInfo& info = v->info();
  auto add_around = [&](int curve, std::map<double, CurveSample>::iterator it) {
    CurveState& c = curves_[curve];
    if (it == c.samples.end()) return;
    if (c.has_next(it)) out.emplace_back(curve, it);
    if (it != c.samples.begin()) out.emplace_back(curve, std::prev(it));
  };
  if (info.dim == FeatureDim::kCurve) {
    const int curve = info.feature - 1;
    CurveState& c = curves_[curve];
    add_around(curve, c.samples.find(info.t));
    if (c.info.closed && info.t == c.info.t_begin) add_around(curve, c.samples.find(c.info.t_end));
  } else if (info.dim == FeatureDim::kCorner) {
    for (const CurveId& id : corners_[info.feature - 1].curves) {
      CurveState& c = curves_[id.value - 1];
      if (c.info.start.value == info.feature) add_around(id.value - 1, c.samples.begin());
      if (c.info.end.value == info.feature) add_around(id.value - 1, std::prev(c.samples.end()));
    }
  }
}

std::optional<std::pair<int, CurveState::Arc>> Refiner::encroached_arc(const Point3& x) {
  std::optional<std::pair<int, CurveState::Arc>> best;
  double best_r2 = -1;
  for (const Vertex_handle& w : zone_feature_vertices_) {
    arcs_of(w, arcs_scratch_);
    for (const auto& [curve, arc] : arcs_scratch_) {
      const CurveSample& s = arc->second;
      if (squared_norm(x - s.center) < s.squared_radius && s.squared_radius > best_r2) {
        best = std::make_pair(curve, arc);
        best_r2 = s.squared_radius;
      }
    }
  }
  return best;
}

void Refiner::recheck_arcs_after(Vertex_handle v) {
  const Point3 x = to_point3(v->point());
  for (const Vertex_handle& w : zone_feature_vertices_) {
    arcs_of(w, arcs_scratch_);
    for (const auto& [curve, arc] : arcs_scratch_) {
      const CurveSample& s = arc->second;
      if (arc->second.vertex == v || std::next(arc)->second.vertex == v) continue;
      if (squared_norm(x - s.center) < s.squared_radius) {
        push_arc(curve, arc, Violation::topological(Rule::kR1NotRestricted));
      }
    }
  }
}

}  // namespace rdmesh::detail
