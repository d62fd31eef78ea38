// The curve level of RR-7912 section 3: rules R1 and R2 on the arcs of D|L_j.
//
// On an arc between consecutive samples p, q of curve L_j, with restricted
// Delaunay ball B(c, r) (c on the arc, |c - p| = |c - q| = r):
//   R1  a vertex not on the arc lies inside B: the edge pq is not in D|L_j
//       and the Voronoi cell of another vertex reaches the arc: refine-edge;
//   R2  r > edge_size(c), or the chord pq is farther than facet_distance from
//       c: refine-edge.
// refine-edge inserts c, on the true curve.
#include "level_curves.h"

#include <algorithm>
#include <iterator>

#include "rdmesh/errors.h"
#include "rdmesh/number_text.h"
#include "simplex_geometry.h"

namespace rdmesh::detail {

namespace {
/// A patch's initial point closer to a curve than this fraction of the edge
/// size is left out: it would sit in the balls of the curve's arcs and force
/// tiny arcs; the curve samples cover that area instead.
constexpr double kCurveKeepOut = 0.25;
/// Each curve starts with this many arcs (its ends and the points between),
/// so that no arc is the whole of a closed curve.
constexpr int kInitialArcs = 3;
}  // namespace

const std::vector<BallRef>& CurveLevel::conflicts() const {
  static const std::vector<BallRef> none;
  return none;
}

CurveRefinementLevel::CurveRefinementLevel(RestrictedCurves& curves, RestrictedComplex& complex,
                                           const Criteria& criteria)
    : curves_(curves), tr_(complex.triangulation()), criteria_(criteria) {}

void CurveRefinementLevel::insert_initial_points(Deadline& deadline, RefinementStats& stats) {
  (void)deadline;  // a handful of points per curve
  const std::vector<CornerInfo>& corners = curves_.corners();
  std::vector<Vertex_handle> corner_vertex(corners.size());
  Cell_handle hint;
  auto insert = [&](const Point3& p, FeatureRef feature, double t) {
    const Vertex_handle v = tr_.insert(to_weighted(p), hint);
    if (v->info().dim() != FeatureDim::kVolume && v->info().dim() != feature.dim()) {
      throw OracleError("two features of the oracle share the point " + point_text(p));
    }
    v->info().feature = feature;
    v->info().t = t;
    hint = v->cell();
    ++stats.initial_points;
    return v;
  };
  for (std::size_t i = 0; i < corners.size(); ++i) {
    corner_vertex[i] = insert(corners[i].point, FeatureRef(CornerId{static_cast<int>(i) + 1}), 0);
  }
  for (std::size_t j = 0; j < curves_.curves().size(); ++j) {
    CurveState& c = curves_.curves()[j];
    const double tb = c.info.t_begin, te = c.info.t_end;
    const FeatureRef id(CurveId{static_cast<int>(j) + 1});
    const double total = c.curve->length(tb, te);
    Vertex_handle first;
    if (c.info.closed) {
      first = insert(c.curve->point(tb), id, tb);
    } else {
      first = corner_vertex.at(c.info.start.value - 1);
    }
    c.samples[tb] = CurveSample{first, to_point3(first->point())};
    for (int k = 1; k < kInitialArcs; ++k) {
      const double t = c.curve->parameter_at_length(tb, total * k / double(kInitialArcs));
      if (t <= tb || t >= te) continue;
      const Vertex_handle v = insert(c.curve->point(t), id, t);
      c.samples[t] = CurveSample{v, to_point3(v->point())};
    }
    const Vertex_handle last = c.info.closed ? first : corner_vertex.at(c.info.end.value - 1);
    c.samples[te] = CurveSample{last, to_point3(last->point())};
  }
}

bool CurveRefinementLevel::keeps_out(const Point3& p, Cell_handle hint) const {
  (void)hint;
  bool near_curve = false;
  for (const CurveState& c : curves_.curves()) {
    const double t = c.curve->closest(p, c.info.t_begin, c.info.t_end);
    const double keep_out = kCurveKeepOut * criteria_.edge_size(p);
    near_curve = near_curve || squared_norm(c.curve->point(t) - p) < keep_out * keep_out;
  }
  return near_curve;
}

void CurveRefinementLevel::queue_initial_arcs() {
  std::vector<CurveState>& curves = curves_.curves();
  for (std::size_t j = 0; j < curves.size(); ++j) {
    CurveState& c = curves[j];
    for (auto a = c.samples.begin(); c.has_next(a); ++a) update_arc(static_cast<int>(j), a);
  }
}

bool CurveRefinementLevel::refine_next(Insertion& insertion) {
  const ArcEntry e = queue_.top();
  queue_.pop();
  const std::optional<CurveState::Arc> a = curves_.find_arc(e.arc);
  // R1 entries stay valid while the arc exists.
  if (!a || (e.rule != Rule::kR1NotRestricted && !violation(e.arc.curve, *a))) return false;
  refine_edge(e.arc.curve, *a, insertion);
  return true;
}

bool CurveRefinementLevel::refine_edge(int curve, CurveState::Arc a, Insertion& insertion) {
  const CurveSample& s = a->second;
  const auto b = std::next(a);
  const VertexInfo info{FeatureRef(CurveId{curve + 1}), s.t_center, -1};
  if (!(s.t_center > a->first && s.t_center < b->first)) {
    insertion.record_guard(info, s.vertex->info());  // the arc is too short to split
    return false;
  }
  const Weighted_point p = to_weighted(s.center);
  if (!insertion.find_zone(p, tr_.locate(p, s.vertex->cell()))) {
    insertion.record_guard(info, s.vertex->info());
    return false;
  }
  const double t = s.t_center;
  const Vertex_handle v = insertion.insert(p, info);
  if (v == Vertex_handle()) return false;
  ++insertion.stats().inserted_edge_centers;
  CurveState& c = curves_.curves()[curve];
  const auto mid = c.samples.emplace_hint(b, t, CurveSample{v, to_point3(v->point())});
  update_arc(curve, a);
  update_arc(curve, mid);
  return true;
}

std::optional<bool> CurveRefinementLevel::refine_encroached(const Point3& x, Insertion& insertion) {
  const auto arc = encroached_arc(x);
  if (!arc) return std::nullopt;
  return refine_edge(arc->first, arc->second, insertion);
}

void CurveRefinementLevel::zone_found(const std::vector<Cell_handle>& zone) {
  zone_feature_vertices_.clear();
  if (curves_.curves().empty()) return;  // no arc to check for encroachment
  for (const Cell_handle& z : zone) {
    for (int k = 0; k < 4; ++k) {
      const Vertex_handle v = z->vertex(k);
      if (tr_.is_infinite(v) || v->info().dim() > FeatureDim::kCurve) continue;
      if (std::find(zone_feature_vertices_.begin(), zone_feature_vertices_.end(), v) ==
          zone_feature_vertices_.end()) {
        zone_feature_vertices_.push_back(v);
      }
    }
  }
}

void CurveRefinementLevel::inserted(Vertex_handle v) {
  // The arcs of the old zone whose ball now contains v lose their edge (R1).
  const Point3 x = to_point3(v->point());
  for (const Vertex_handle& w : zone_feature_vertices_) {
    curves_.arcs_of(w, arcs_scratch_);
    for (const auto& [curve, arc] : arcs_scratch_) {
      const CurveSample& s = arc->second;
      if (arc->second.vertex == v || std::next(arc)->second.vertex == v) continue;
      if (squared_norm(x - s.center) < s.squared_radius) {
        push(curve, arc, Violation::topological(Rule::kR1NotRestricted));
      }
    }
  }
}

Violation CurveRefinementLevel::update_arc(int curve, CurveState::Arc a) {
  CurveState& c = curves_.curves()[curve];
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
  Violation worst = violation(curve, a);
  // R1: is the ball empty? Its nearest vertex must be p or q.
  const Vertex_handle w = tr_.nearest_power_vertex(
      Kernel::Point_3(s.center.x, s.center.y, s.center.z), a->second.vertex->cell());
  if (w != a->second.vertex && w != b->second.vertex &&
      squared_norm(to_point3(w->point()) - s.center) < s.squared_radius) {
    worst = Violation::topological(Rule::kR1NotRestricted);
  }
  if (worst) push(curve, a, worst);
  return worst;
}

Violation CurveRefinementLevel::violation(int curve, CurveState::Arc a) const {
  (void)curve;
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
  return worst;
}

void CurveRefinementLevel::push(int curve, CurveState::Arc a, const Violation& violation) {
  queue_.push({violation.priority, next_order_++,
               ArcRef{curve, a->first, a->second.vertex, std::next(a)->second.vertex},
               violation.rule});
}

std::optional<std::pair<int, CurveState::Arc>> CurveRefinementLevel::encroached_arc(
    const Point3& x) {
  std::optional<std::pair<int, CurveState::Arc>> best;
  double best_r2 = -1;
  for (const Vertex_handle& w : zone_feature_vertices_) {
    curves_.arcs_of(w, arcs_scratch_);
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

}  // namespace rdmesh::detail
