// A face's (u, v) cells and their boundary classification (uv_cells.h).
#include "uv_cells.h"

#include <BRepAdaptor_Curve2d.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <cmath>
#include <gp_Pnt2d.hxx>

#include "cad_model.h"

namespace rdmesh::cad {
namespace {

// Each pcurve cut until the chord strays less than `eps` from its midpoint
// sample; reach = twice that sagitta (the margin is added later).
void add_chords(const BRepAdaptor_Curve2d& c, double ta, double tb, const gp_Pnt2d& pa,
                const gp_Pnt2d& pb, int depth, double eps, std::vector<UvSegment>& out) {
  const double tm = 0.5 * (ta + tb);
  const gp_Pnt2d pm = c.Value(tm);
  const double sag = pm.Distance(gp_Pnt2d(0.5 * (pa.X() + pb.X()), 0.5 * (pa.Y() + pb.Y())));
  if (sag > eps && depth < 12) {
    add_chords(c, ta, tm, pa, pm, depth + 1, eps, out);
    add_chords(c, tm, tb, pm, pb, depth + 1, eps, out);
    return;
  }
  out.push_back({pa.X(), pa.Y(), pb.X(), pb.Y(), 2 * sag});
}

double point_segment(double u, double v, const UvSegment& s) {
  const double eu = s.bu - s.au, ev = s.bv - s.av;
  const double l2 = eu * eu + ev * ev;
  double t = l2 > 0 ? ((u - s.au) * eu + (v - s.av) * ev) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(u - (s.au + t * eu), v - (s.av + t * ev));
}

double orient(double au, double av, double bu, double bv, double cu, double cv) {
  return (bu - au) * (cv - av) - (bv - av) * (cu - au);
}

}  // namespace

std::vector<UvSegment> boundary_segments(const FacePatch& f) {
  std::vector<UvSegment> out;
  std::vector<gp_Pnt2d> ends;
  const double uv_size = std::hypot(f.u1 - f.u0, f.v1 - f.v0);
  const double eps = 1e-3 * uv_size;
  for (TopExp_Explorer ex(f.face, TopAbs_EDGE); ex.More(); ex.Next()) {
    const BRepAdaptor_Curve2d c(TopoDS::Edge(ex.Current()), f.face);
    const double t0 = c.FirstParameter(), t1 = c.LastParameter();
    constexpr int kStart = 8;
    gp_Pnt2d prev = c.Value(t0);
    ends.push_back(prev);
    for (int k = 1; k <= kStart; ++k) {
      const double ta = t0 + (t1 - t0) * (k - 1) / kStart, tb = t0 + (t1 - t0) * k / kStart;
      const gp_Pnt2d next = c.Value(tb);
      add_chords(c, ta, tb, prev, next, 0, eps, out);
      prev = next;
    }
    ends.push_back(prev);
  }
  // Consecutive pcurves meet only within their vertex tolerance: the widest gap
  // between an end and the nearest other end joins every reach.
  double gap = 0;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    double nearest = HUGE_VAL;
    for (std::size_t j = 0; j < ends.size(); ++j) {
      if (j != i) nearest = std::min(nearest, ends[i].Distance(ends[j]));
    }
    if (nearest < HUGE_VAL) gap = std::max(gap, nearest);
  }
  const double margin = 1e-4 * uv_size + 2 * BRep_Tool::Tolerance(f.face) + gap;
  for (UvSegment& s : out) s.reach += margin;
  return out;
}

void UvCells::normalise(double& u, double& v) const {
  if (u_period > 0) {
    const double lo = u0 - 1e-9 * u_period;
    u -= u_period * std::floor((u - lo) / u_period);
  }
  if (v_period > 0) {
    const double lo = v0 - 1e-9 * v_period;
    v -= v_period * std::floor((v - lo) / v_period);
  }
}

UvState UvCells::state_at(double u, double v) const {
  if (nodes.empty()) return UvState::boundary;
  normalise(u, v);
  const double eu = 1e-9 * (u1 - u0), ev = 1e-9 * (v1 - v0);
  if (u < u0 - eu || u > u1 + eu || v < v0 - ev || v > v1 + ev) return UvState::outside;
  int i = 0;
  while (nodes[i].child >= 0) {
    const Node& n = nodes[i];
    i = n.child + ((n.axis == 0 ? u : v) > n.split ? 1 : 0);
  }
  const Node& leaf = nodes[i];
  if (leaf.state != UvState::boundary || !leaf.has_reference) return leaf.state;
  return resolve(leaf, u, v);
}

UvState UvCells::resolve(const Node& leaf, double u, double v) const {
  bool inside = leaf.reference_inside;
  const double ru = leaf.ref_u, rv = leaf.ref_v;
  const double scale = std::max(u1 - u0, v1 - v0);
  for (int k = leaf.first; k < leaf.first + leaf.count; ++k) {
    const UvSegment& s = segments[segment_refs[k]];
    if (point_segment(u, v, s) <= s.reach) return UvState::boundary;  // in a tube
    const double o1 = orient(s.au, s.av, s.bu, s.bv, ru, rv);
    const double o2 = orient(s.au, s.av, s.bu, s.bv, u, v);
    const double o3 = orient(ru, rv, u, v, s.au, s.av);
    const double o4 = orient(ru, rv, u, v, s.bu, s.bv);
    const double eps = 1e-12 * scale * scale;
    if (std::fabs(o3) <= eps || std::fabs(o4) <= eps) return UvState::boundary;  // through an end
    if ((o1 > 0) != (o2 > 0) && (o3 > 0) != (o4 > 0)) inside = !inside;
  }
  return inside ? UvState::inside : UvState::outside;
}

void UvCells::set_boundary_leaf(int index, double cu0, double cu1, double cv0, double cv1,
                                const std::vector<int>& chords, const BRepTopAdaptor_FClass2d& c) {
  Node& n = nodes[index];
  n.state = UvState::boundary;
  n.first = static_cast<int>(segment_refs.size());
  n.count = static_cast<int>(chords.size());
  segment_refs.insert(segment_refs.end(), chords.begin(), chords.end());
  // The first of a few points of the cell outside every tube whose state the
  // classifier gives as IN or OUT.
  for (int k = 0; k < 25; ++k) {
    const int j = (k + 12) % 25;  // a 5 x 5 grid, from its centre on
    const double u = cu0 + ((2 * (j % 5) + 1) / 10.0) * (cu1 - cu0);
    const double v = cv0 + ((2 * (j / 5) + 1) / 10.0) * (cv1 - cv0);
    bool clear = true;
    for (int s : chords) clear = clear && point_segment(u, v, segments[s]) > segments[s].reach;
    if (!clear) continue;
    const TopAbs_State state = c.Perform(gp_Pnt2d(u, v));
    if (state != TopAbs_IN && state != TopAbs_OUT) continue;
    Node& m = nodes[index];
    m.has_reference = true;
    m.reference_inside = state == TopAbs_IN;
    m.ref_u = u, m.ref_v = v;
    return;
  }
}

}  // namespace rdmesh::cad
