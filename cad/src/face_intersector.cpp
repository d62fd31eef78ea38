// The exact segment/face intersector (face_intersector.h).
#include "face_intersector.h"

#include <TopAbs_State.hxx>
#include <algorithm>
#include <cmath>
#include <limits>

#include "analytic_roots.h"
#include "thread_state.h"

namespace rdmesh::cad {
namespace {

constexpr int kMaxDepth = 8;    // subdivision levels below a tessellation triangle
constexpr int kMaxWork = 4000;  // subdivisions per query before OpenCASCADE takes over
constexpr double kGrow = 1e-9;  // barycentric slack of "a root inside the triangle"
constexpr double kTangentCosine = 1e-6;
// How good a crossing is, among crossings at the same place.
constexpr int kGrazing = 0, kOnBoundary = 1, kTransversal = 2;

// Barycentric coordinates of x (in the triangle's plane) with respect to p0 p1 p2.
void barycentric(const Point3& x, const Point3 p[3], double b[3]) {
  const Point3 e1 = p[1] - p[0], e2 = p[2] - p[0], r = x - p[0];
  const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
  const double r1 = dot(r, e1), r2 = dot(r, e2);
  const double det = d11 * d22 - d12 * d12;
  b[1] = det > 0 ? (d22 * r1 - d12 * r2) / det : 1.0 / 3;
  b[2] = det > 0 ? (d11 * r2 - d12 * r1) / det : 1.0 / 3;
  b[0] = 1 - b[1] - b[2];
}

double near_period(double x, double ref, double period) {
  return period > 0 ? x - period * std::round((x - ref) / period) : x;
}

}  // namespace

RayQuery::RayQuery(const CadOracle::Model& m, ThreadState& ts, const Point3& a, const Point3& d,
                   double length)
    : m_(m), ts_(ts), a_(a), d_(d), length_(length), slack_(1e-9 * m.box.diagonal()) {
  ts_.begin_query();
}

double RayQuery::reach() const {
  if (!best_) return length_ + m_.tolerance;
  // A better crossing within the tolerance of a grazing or on-boundary one replaces it.
  return best_rank_ < kTransversal ? best_->distance + m_.tolerance : best_->distance;
}

void RayQuery::visit(int index) {
  const Candidate& c = m_.candidates[index];
  FaceState& fs = ts_.face(c.face);
  if (fs.occt_done) return;
  if (m_.faces[c.face].kind == SurfaceKind::parametric) {
    if (c.triangle >= 0) return solve(m_.triangles[c.triangle], 0);
    return occt(c.face, 0, std::min(reach(), length_));  // no tessellation
  }
  if (!fs.closed_form_done) closed_form(c.face);
  fs.closed_form_done = true;
}

void RayQuery::closed_form(int face) {
  AnalyticRoot roots[2];
  const FacePatch& f = m_.faces[face];
  const int n = analytic_roots(f, a_, d_, roots);
  for (int i = 0; i < n; ++i) {
    if (roots[i].w < 0 || roots[i].w > length_ || roots[i].w >= reach()) continue;
    Point3 p, su, sv;
    analytic_d1(f, roots[i].u, roots[i].v, p, su, sv);
    const Point3 x = a_ + roots[i].w * d_;
    if (distance(p, x) > m_.tolerance) {  // parameters off the root
      return occt(face, 0, std::min(reach(), length_));
    }
    consider(face, roots[i].w, roots[i].u, roots[i].v, x, su, sv, -1);
  }
}

void RayQuery::solve(const SurfaceTriangle& t, int depth) {
  // The triangle's window on the whole line, then on the segment still wanted.
  // A crossing lies on the surface, within t.deviation of t: only rounding is
  // added (not the tolerance, or near misses would never be told apart).
  const double r = t.deviation + slack_;
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  double lo = -kInfinity, hi = kInfinity;
  if (!clip_line(a_, d_, triangle_box(t, r), lo, hi) || !window(t, r, lo, hi)) return;
  const double seg_lo = std::max(lo, 0.0), seg_hi = std::min(hi, std::min(reach(), length_));
  if (seg_lo > seg_hi) return;
  const double c = dot(t.axis, d_);
  const bool transversal = std::fabs(c) > t.sin_cone;  // at most one crossing over t
  if (transversal || depth >= kMaxDepth) {
    // Newton from the line's crossing with t's plane (kept in the window).
    const double w =
        c != 0 ? std::clamp(dot(t.axis, t.p[0] - a_) / c, seg_lo, seg_hi) : 0.5 * (seg_lo + seg_hi);
    const Point3 foot = closest_on_triangle(a_ + w * d_, t.p[0], t.p[1], t.p[2]);
    double b[3];
    barycentric(foot, t.p, b);
    const double u = b[0] * t.uv[0][0] + b[1] * t.uv[1][0] + b[2] * t.uv[2][0];
    const double v = b[0] * t.uv[0][1] + b[1] * t.uv[1][1] + b[2] * t.uv[2][1];
    const LineRoot root = newton_on_line(ts_.surface(t.face), a_, d_, u, v, w, 0.5 * m_.tolerance);
    if (root.converged) {
      consider_root(t.face, root);
      if (transversal && settles(t, root, c, lo, hi)) return;
    }
  }
  // A grazing segment, or Newton failed or ended elsewhere: look closer, down to
  // the finest level, where a grazing crossing may hide a second one next to it.
  if (depth >= kMaxDepth || ++work_ > kMaxWork) return occt(t.face, seg_lo, seg_hi);
  subdivide(t, depth);
}

bool RayQuery::window(const SurfaceTriangle& t, double r, double& lo, double& hi) const {
  // Within r of t's plane: |h0 + c w| <= r.
  const double c = dot(t.axis, d_), h0 = dot(t.axis, a_ - t.p[0]);
  if (c == 0) {
    if (std::fabs(h0) > r) return false;
  } else {
    double w0 = (-r - h0) / c, w1 = (r - h0) / c;
    if (w0 > w1) std::swap(w0, w1);
    lo = std::max(lo, w0), hi = std::min(hi, w1);
    if (lo > hi) return false;
  }
  // The shadow of the line on t's plane inside t grown by r (each edge moved out by r).
  const Point3 normal = cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
  const double longest = std::max({squared_norm(t.p[1] - t.p[0]), squared_norm(t.p[2] - t.p[1]),
                                   squared_norm(t.p[0] - t.p[2])});
  if (!(norm(normal) > 1e-9 * longest)) return true;  // a degenerate triangle: box and slab only
  const double side = dot(normal, t.axis) > 0 ? 1 : -1;
  for (int k = 0; k < 3; ++k) {
    const Point3 e = t.p[(k + 1) % 3] - t.p[k];
    Point3 m = side * cross(t.axis, e);  // in t's plane, pointing into t
    const double l = norm(m);
    if (!(l > 0)) continue;
    m = (1 / l) * m;
    // m . (a + w d - p_k) >= -r
    const double f0 = dot(m, a_ - t.p[k]) + r, f1 = dot(m, d_);
    if (f1 == 0) {
      if (f0 < 0) return false;
      continue;
    }
    const double w = -f0 / f1;
    if (f1 > 0) {
      lo = std::max(lo, w);
    } else {
      hi = std::min(hi, w);
    }
    if (lo > hi) return false;
  }
  return true;
}

void RayQuery::subdivide(const SurfaceTriangle& t, int depth) {
  const SurfaceEvaluator& s = ts_.surface(t.face);
  // Nodes 0..2 are t's, 3..5 the midpoints of edges 01, 12, 20.
  double uv[6][2];
  Point3 p[6], n[6];
  for (int k = 0; k < 3; ++k) {
    uv[k][0] = t.uv[k][0], uv[k][1] = t.uv[k][1], p[k] = t.p[k], n[k] = t.n[k];
    const int l = (k + 1) % 3;
    uv[3 + k][0] = 0.5 * (t.uv[k][0] + t.uv[l][0]);
    uv[3 + k][1] = 0.5 * (t.uv[k][1] + t.uv[l][1]);
    Point3 su, sv;
    s.d1(uv[3 + k][0], uv[3 + k][1], p[3 + k], su, sv);
    const Point3 nn = cross(su, sv);
    const double len = norm(nn);
    // Zero where degenerate: measure_triangle() then samples the limit normal.
    n[3 + k] = len > 1e-12 * norm(su) * norm(sv) && len > 0 ? (1 / len) * nn : Point3{};
  }
  constexpr int kChildren[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};
  for (const auto& c : kChildren) {
    SurfaceTriangle child;
    child.face = t.face;
    for (int k = 0; k < 3; ++k) {
      child.uv[k][0] = uv[c[k]][0], child.uv[k][1] = uv[c[k]][1];
      child.p[k] = p[c[k]], child.n[k] = n[c[k]];
    }
    measure_triangle(s, child);
    solve(child, depth + 1);
  }
}

bool RayQuery::settles(const SurfaceTriangle& t, const LineRoot& root, double c, double lo,
                       double hi) const {
  // A root in the window crossing the way the surface over t would (same sign
  // of n . d): over a transversal triangle the line crosses at most once there.
  const Point3 n = cross(root.su, root.sv);
  if (root.w >= lo && root.w <= hi && dot(n, d_) * c > 0) return true;
  // A root inside t is its only one (t is transversal).
  const SurfaceEvaluator& s = ts_.surface(t.face);
  const double cu = (t.uv[0][0] + t.uv[1][0] + t.uv[2][0]) / 3;
  const double cv = (t.uv[0][1] + t.uv[1][1] + t.uv[2][1]) / 3;
  const double u = near_period(root.u, cu, s.u_period()), v = near_period(root.v, cv, s.v_period());
  // Barycentric coordinates in (u, v), where the triangle is never degenerate.
  const double e1u = t.uv[1][0] - t.uv[0][0], e1v = t.uv[1][1] - t.uv[0][1];
  const double e2u = t.uv[2][0] - t.uv[0][0], e2v = t.uv[2][1] - t.uv[0][1];
  const double ru = u - t.uv[0][0], rv = v - t.uv[0][1];
  const double det = e1u * e2v - e1v * e2u;
  if (det == 0) return false;
  const double b1 = (ru * e2v - rv * e2u) / det, b2 = (e1u * rv - e1v * ru) / det;
  return b1 >= -kGrow && b2 >= -kGrow && 1 - b1 - b2 >= -kGrow;
}

void RayQuery::consider_root(int face, const LineRoot& root) {
  consider(face, root.w, root.u, root.v, root.point, root.su, root.sv, -1);
}

void RayQuery::consider(int face, double w, double u, double v, const Point3& point,
                        const Point3& su, const Point3& sv, int state, bool tangent) {
  if (w < 0 || w > length_ || w >= reach()) return;
  const FacePatch& f = m_.faces[face];
  if (state < 0) state = ts_.classify(face, u, v);
  if (state != TopAbs_IN && state != TopAbs_ON) return;
  Point3 n = cross(su, sv);
  if (f.face.Orientation() == TopAbs_REVERSED) n = -1.0 * n;
  const double nn = norm(n);
  RayHit h;
  h.distance = w;
  h.face = face;
  h.point = point;
  h.cosine = nn > 0 ? dot(n, d_) / nn : 0.0;
  const bool grazing = tangent || std::fabs(h.cosine) < kTangentCosine;
  h.tangent = grazing || state == TopAbs_ON;
  const int rank = grazing ? kGrazing : (state == TopAbs_ON ? kOnBoundary : kTransversal);
  // Crossings within the tolerance of each other are the same place: the better
  // one wins (a segment along a wall grazes it where it crosses the face below).
  if (best_ && std::fabs(w - best_->distance) <= m_.tolerance &&
      (rank < best_rank_ || (rank == best_rank_ && w >= best_->distance))) {
    return;
  }
  best_ = h;
  best_rank_ = rank;
}

void RayQuery::occt(int face, double w0, double w1) {
  FaceState& fs = ts_.face(face);
  if (fs.occt_done) return;
  for (int k = 0; k < fs.occt_windows; ++k) {
    if (fs.occt_window[k][0] <= w0 && w1 <= fs.occt_window[k][1]) return;  // done already
  }
  if (fs.occt_windows == FaceState::kWindows) {  // too many spots: the whole segment
    w0 = 0, w1 = std::min(reach(), length_);
    fs.occt_done = true;
  } else {
    fs.occt_window[fs.occt_windows][0] = w0;
    fs.occt_window[fs.occt_windows][1] = w1;
    ++fs.occt_windows;
  }
  std::vector<OcctFaceIntersector::Hit>& hits = ts_.occt_hits;
  hits.clear();
  try {
    ts_.occt(face).intersect(a_, d_, w0, w1, hits);
  } catch (const Standard_Failure&) {
    return;  // a degenerate sub-problem of this face: no crossing found there
  }
  const SurfaceEvaluator& s = ts_.surface(face);
  for (const OcctFaceIntersector::Hit& h : hits) {
    Point3 p, su, sv;
    s.d1(h.u, h.v, p, su, sv);
    consider(face, h.w, h.u, h.v, h.point, su, sv, h.state, h.tangent);
  }
}

}  // namespace rdmesh::cad
