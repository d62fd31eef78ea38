#include "curve_smoothing.h"

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "tet_smoothing.h"

namespace rdmesh::detail {
namespace {

constexpr int kIterations = 4;
/// Trial steps: these fractions of the parameter gap to each chain neighbour.
constexpr double kFractions[] = {0.4, 0.2, 0.1, 0.05};

}  // namespace

bool smooth_on_curve(TetTopology& topo, const PatchSurface& surface,
                     std::vector<double>& parameters, int v) {
  const int id = surface.curve_of(v);
  if (id == 0 || topo.tets_of(v).empty()) return false;
  const CurveInfo& info = surface.curve_info(id);
  const Curve& curve = surface.oracle().curve(CurveId{id});
  const auto [a, b] = surface.chain_neighbours(v);
  if (parameters.size() < static_cast<std::size_t>(topo.vertex_count())) {
    parameters.resize(static_cast<std::size_t>(topo.vertex_count()), std::nan(""));
  }
  // The parameter of a vertex on this curve, found once (a corner's depends on the curve).
  const auto parameter = [&](int w) {
    if (surface.curve_of(w) != id) return curve.closest(topo.point(w), info.t_begin, info.t_end);
    double& t = parameters[static_cast<std::size_t>(w)];
    if (std::isnan(t)) t = curve.closest(topo.point(w), info.t_begin, info.t_end);
    return t;
  };
  // The parameters of v and of its neighbours; v strictly between them, and
  // at its own point (else the curve's parametrization is not followed here).
  const double tv = parameter(v);
  double ta = parameter(a);
  double tb = parameter(b);
  if (ta > tb) std::swap(ta, tb);
  const double tolerance = surface.oracle().tolerance();
  if (!(ta < tv && tv < tb) || !(distance(curve.point(tv), topo.point(v)) <= tolerance) ||
      !(distance(curve.point(ta), topo.point(a)) <= tolerance) ||
      !(distance(curve.point(tb), topo.point(b)) <= tolerance)) {
    return false;
  }
  double q = std::numeric_limits<double>::infinity();
  for (const int t : topo.tets_of(v)) q = std::min(q, topo.quality(t));
  const Star star(topo, v);
  // The positions reached, each better than the one before.
  std::vector<std::pair<Point3, double>> path;
  double t = tv;
  for (int it = 0; it < kIterations; ++it) {
    double best_t = t, best_q = q;
    Point3 best_p;
    for (const double f : kFractions) {
      for (const double end : {ta, tb}) {
        const double s = t + f * (end - t);
        const Point3 p = curve.point(s);
        const double qs = star.min_quality(p, best_q);
        if (qs > best_q && surface.keeps_normals(topo, v, p)) {
          best_t = s;
          best_q = qs;
          best_p = p;
        }
      }
    }
    if (!(best_q > q)) break;
    t = best_t;
    q = best_q;
    path.push_back({best_p, best_t});
  }
  // The last position whose triangles and feature edges stay within the facet
  // distance of their patches and curve, and whose feature edges keep R2's
  // size (or get no longer, where they broke it before).
  const auto edge_near = [&](const Point3& p, int w) {
    const Point3 m = 0.5 * (p + topo.point(w));
    return distance(curve.point(curve.closest(m, ta, tb)), m) <= surface.facet_distance(m);
  };
  const auto edge_short = [&](const Point3& p, int w) {
    const double after = distance(p, topo.point(w));
    return after <= 2 * surface.edge_size(0.5 * (p + topo.point(w))) ||
           after <= distance(topo.point(v), topo.point(w));
  };
  for (auto p = path.rbegin(); p != path.rend(); ++p) {
    if (edge_near(p->first, a) && edge_near(p->first, b) && edge_short(p->first, a) &&
        edge_short(p->first, b) && surface.near_surface(topo, v, p->first)) {
      topo.move(v, p->first);
      parameters[static_cast<std::size_t>(v)] = p->second;
      return true;
    }
  }
  return false;
}

}  // namespace rdmesh::detail
