// Closest points on faces (face_projection.h).
#include "face_projection.h"

#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <algorithm>
#include <cmath>
#include <limits>

#include "thread_state.h"

namespace rdmesh::cad {
namespace {

gp_Pnt to_gp(const Point3& p) { return {p.x, p.y, p.z}; }
Point3 to_point(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
Point3 to_point(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }

bool accepted(TopAbs_State s) { return s == TopAbs_IN || s == TopAbs_ON; }

// The nearest point of the face's triangles to p, as a (u, v) guess.
bool tessellation_guess(const CadOracle::Model& m, const FacePatch& f, const Point3& p, double& u,
                        double& v) {
  if (f.triangle_tree.empty()) return false;
  double best = std::numeric_limits<double>::infinity();
  int best_t = -1;
  Point3 best_x;
  f.triangle_tree.nearest([&](const Box3& b) { return std::sqrt(squared_distance(b, p)); },
                          [&](int i, double& bound) {
                            const SurfaceTriangle& t = m.triangles[f.first_triangle + i];
                            const Point3 x = closest_on_triangle(p, t.p[0], t.p[1], t.p[2]);
                            const double d = distance(x, p);
                            if (d < bound) bound = d, best = d, best_t = i, best_x = x;
                          },
                          best);
  if (best_t < 0) return false;
  const SurfaceTriangle& t = m.triangles[f.first_triangle + best_t];
  const Point3 e1 = t.p[1] - t.p[0], e2 = t.p[2] - t.p[0], r = best_x - t.p[0];
  const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
  const double det = d11 * d22 - d12 * d12;
  double b1 = 1.0 / 3, b2 = 1.0 / 3;
  if (det > 0) {
    b1 = (d22 * dot(r, e1) - d12 * dot(r, e2)) / det;
    b2 = (d11 * dot(r, e2) - d12 * dot(r, e1)) / det;
  }
  const double b0 = 1 - b1 - b2;
  u = b0 * t.uv[0][0] + b1 * t.uv[1][0] + b2 * t.uv[2][0];
  v = b0 * t.uv[0][1] + b1 * t.uv[1][1] + b2 * t.uv[2][1];
  return true;
}

// The closest point of one edge curve: nearest polyline point, then Newton on
// |C(t) - p|^2 within the edge's parameter range.
Point3 closest_on_curve(const BoundaryCurve& c, const Point3& p, double tolerance) {
  double best = std::numeric_limits<double>::infinity(), t = c.t.front();
  for (std::size_t k = 0; k + 1 < c.points.size(); ++k) {
    const Point3 e = c.points[k + 1] - c.points[k];
    const double l2 = squared_norm(e);
    const double s = l2 > 0 ? std::clamp(dot(p - c.points[k], e) / l2, 0.0, 1.0) : 0.0;
    const double d = squared_norm(c.points[k] + s * e - p);
    if (d < best) best = d, t = c.t[k] + s * (c.t[k + 1] - c.t[k]);
  }
  const double t0 = c.t.front(), t1 = c.t.back();
  gp_Pnt q;
  gp_Vec d1, d2;
  c.curve->D2(t, q, d1, d2);
  for (int it = 0; it < 20; ++it) {
    const Point3 e = to_point(q) - p, c1 = to_point(d1), c2 = to_point(d2);
    double h = dot(c1, c1) + dot(e, c2);
    if (!(h > 0)) h = dot(c1, c1);
    if (!(h > 0)) break;
    const double tn = std::clamp(t - dot(e, c1) / h, t0, t1);
    gp_Pnt qn;
    gp_Vec d1n, d2n;
    c.curve->D2(tn, qn, d1n, d2n);
    if (squared_norm(to_point(qn) - p) > squared_norm(e)) break;  // no progress
    const double moved = qn.Distance(q);
    t = tn, q = qn, d1 = d1n, d2 = d2n;
    if (moved <= 0.01 * tolerance) break;
  }
  return to_point(q);
}

std::optional<Point3> closest_on_boundary(const FacePatch& f, const Point3& p, double tolerance) {
  std::optional<Point3> best;
  for (const BoundaryCurve& c : f.boundary) {
    const Point3 x = closest_on_curve(c, p, tolerance);
    if (!best || distance(x, p) < distance(*best, p)) best = x;
  }
  return best;
}

// Newton from the nearest point of the face's tessellation: the surface's foot
// when the face holds it, else the nearest point of the face's boundary curves;
// nullopt without a seed, when Newton fails, or when the foot is outside and the
// face has no boundary curves. A foot at `beyond` or farther from p is returned
// unclassified: the face is a part of its surface, so none of it is nearer.
std::optional<Point3> newton_closest(const CadOracle::Model& m, ThreadState& ts, int face,
                                     const Point3& p, double beyond) {
  const FacePatch& f = m.faces[face];
  double u = 0, v = 0;
  if (!tessellation_guess(m, f, p, u, v)) return std::nullopt;
  const SurfaceFoot foot = newton_foot(ts.surface(face), p, u, v, m.tolerance);
  if (!foot.converged) return std::nullopt;
  if (distance(foot.point, p) >= beyond) return foot.point;
  if (accepted(ts.classify(face, foot.u, foot.v))) return foot.point;
  // The foot is outside the trimmed face: the closest point is on its boundary.
  return closest_on_boundary(f, p, m.tolerance);
}

}  // namespace

std::optional<Point3> project_on_face(const CadOracle::Model& m, ThreadState& ts, int face,
                                      const Point3& p) {
  if (std::optional<Point3> x = newton_closest(m, ts, face, p, HUGE_VAL)) return x;
  const FacePatch& f = m.faces[face];
  double u = 0, v = 0;
  GeomAPI_ProjectPointOnSurf proj(to_gp(p), f.surface, f.u0, f.u1, f.v0, f.v1);
  if (proj.NbPoints() > 0) {
    proj.LowerDistanceParameters(u, v);
    if (accepted(ts.classify(face, u, v))) return to_point(proj.NearestPoint());
  }
  if (std::optional<Point3> b = closest_on_boundary(f, p, m.tolerance)) return b;
  BRepExtrema_DistShapeShape dist(BRepBuilderAPI_MakeVertex(to_gp(p)).Vertex(), f.face);
  if (dist.IsDone() && dist.NbSolution() > 0) return to_point(dist.PointOnShape2(1));
  return std::nullopt;
}

std::optional<std::array<double, 2>> foot_parameters(const CadOracle::Model& m, ThreadState& ts,
                                                     int face, const Point3& p) {
  const FacePatch& f = m.faces[face];
  double u = 0, v = 0;
  if (tessellation_guess(m, f, p, u, v)) {
    const SurfaceFoot foot = newton_foot(ts.surface(face), p, u, v, m.tolerance);
    if (foot.converged) return std::array<double, 2>{foot.u, foot.v};
  }
  GeomAPI_ProjectPointOnSurf proj(to_gp(p), f.surface, f.u0, f.u1, f.v0, f.v1);
  if (proj.NbPoints() == 0) return std::nullopt;
  proj.LowerDistanceParameters(u, v);
  return std::array<double, 2>{u, v};
}

double distance_to_face(const CadOracle::Model& m, ThreadState& ts, int face, const Point3& p,
                        double limit) {
  const std::optional<Point3> x = newton_closest(m, ts, face, p, limit);
  return x ? std::min(limit, distance(*x, p)) : limit;
}

}  // namespace rdmesh::cad
