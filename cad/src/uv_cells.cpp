// A face's (u, v) cells and their boundary classification (uv_cells.h).
#include "uv_cells.h"

#include <BRepAdaptor_Curve2d.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dInt_Geom2dCurveTool.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <gp_Pnt2d.hxx>

#include "cad_model.h"

namespace rdmesh::cad {
namespace {

// Each pcurve cut until the chord strays less than `eps` from its midpoint
// sample; reach = twice that sagitta (the margin is added later). The chords'
// parameter ranges go to `ranges` when given.
void add_chords(const BRepAdaptor_Curve2d& c, double ta, double tb, const gp_Pnt2d& pa,
                const gp_Pnt2d& pb, int depth, double eps, std::vector<UvSegment>& out,
                std::vector<std::array<double, 2>>* ranges) {
  const double tm = 0.5 * (ta + tb);
  const gp_Pnt2d pm = c.Value(tm);
  const double sag = pm.Distance(gp_Pnt2d(0.5 * (pa.X() + pb.X()), 0.5 * (pa.Y() + pb.Y())));
  if (sag > eps && depth < 12) {
    add_chords(c, ta, tm, pa, pm, depth + 1, eps, out, ranges);
    add_chords(c, tm, tb, pm, pb, depth + 1, eps, out, ranges);
    return;
  }
  out.push_back({pa.X(), pa.Y(), pb.X(), pb.Y(), 2 * sag});
  if (ranges) ranges->push_back({ta, tb});
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

// Whether segment [(ru, rv), (u, v)] crosses chord s (1) or not (0), or passes
// within `eps` (an orientation) of one of its ends, where parity is undecided (-1).
int crossing(const UvSegment& s, double ru, double rv, double u, double v, double eps) {
  const double o1 = orient(s.au, s.av, s.bu, s.bv, ru, rv);
  const double o2 = orient(s.au, s.av, s.bu, s.bv, u, v);
  const double o3 = orient(ru, rv, u, v, s.au, s.av);
  const double o4 = orient(ru, rv, u, v, s.bu, s.bv);
  if (std::fabs(o3) <= eps || std::fabs(o4) <= eps) return -1;
  return (o1 > 0) != (o2 > 0) && (o3 > 0) != (o4 > 0) ? 1 : 0;
}

// The widest tube a chord gets, x the (u, v) box diagonal (where the
// surface's stretch vanishes, as at a pole).
constexpr double kReachCap = 0.05;

// How far in (u, v) a 3D distance `d` can reach from chord s: d over the
// smallest stretch of the surface's Jacobian [Su Sv] at the chord's middle, at
// most `cap`. A degenerated edge (a pole) is one 3D point: the points within d
// of it lie within d over the stretch across the chord (Sv at a sphere's
// pole, where Su vanishes and the smallest stretch would give the cap).
double uv_reach(const GeomAdaptor_Surface& s, const UvSegment& chord, bool degenerated, double d,
                double cap) {
  gp_Pnt p;
  gp_Vec su, sv;
  s.D1(0.5 * (chord.au + chord.bu), 0.5 * (chord.av + chord.bv), p, su, sv);
  const double a = su.SquareMagnitude(), b = su.Dot(sv), c = sv.SquareMagnitude();
  double smallest = 0.5 * (a + c) - std::sqrt(0.25 * (a - c) * (a - c) + b * b);
  const double eu = chord.bu - chord.au, ev = chord.bv - chord.av, l = std::hypot(eu, ev);
  if (degenerated && l > 0) smallest = (su * (-ev / l) + sv * (eu / l)).SquareMagnitude();
  return smallest > 0 && d < cap * std::sqrt(smallest) ? d / std::sqrt(smallest) : cap;
}

}  // namespace

void boundary_segments(const FacePatch& f, std::vector<UvSegment>& out,
                       std::vector<UvSegment>& fine, std::vector<UvSegment>& poles) {
  out.clear();
  fine.clear();
  std::vector<double> edge_tolerance, fine_tolerance;  // per chord
  std::vector<char> degenerated, fine_degenerated;     // per chord: of a degenerated edge
  std::vector<std::array<double, 2>> ranges;           // per chord of the edge at hand
  std::vector<gp_Pnt2d> ends;
  const double uv_size = std::hypot(f.u1 - f.u0, f.v1 - f.v0);
  const double eps = 1e-4 * uv_size, fine_eps = 1e-5 * uv_size;
  const double face_tolerance = BRep_Tool::Tolerance(f.face);
  for (TopExp_Explorer ex(f.face, TopAbs_EDGE); ex.More(); ex.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(ex.Current());
    // An INTERNAL edge (a contact line a general fuse imprinted, say) has the
    // face on both sides and an EXTERNAL one on neither: neither bounds the
    // face, and as chords they would flip the parity of every point across
    // them; their loose ends made the gap below the width of the face, so
    // that every point of the bearing balls' faces went to the classifier.
    if (edge.Orientation() == TopAbs_INTERNAL || edge.Orientation() == TopAbs_EXTERNAL) continue;
    const BRepAdaptor_Curve2d c(edge, f.face);
    // Start at least as densely as the face classifier samples the pcurve (and
    // four points per C2 piece): a narrow excursion of a poorly approximated
    // pcurve between samples would be missed by the sagitta test alone.
    const double t0 = c.FirstParameter(), t1 = c.LastParameter();
    const int kStart = std::clamp(
        std::max(4 * Geom2dInt_Geom2dCurveTool::NbSamples(c), 4 * c.NbIntervals(GeomAbs_C2)), 8,
        4000);
    gp_Pnt2d prev = c.Value(t0);
    ends.push_back(prev);
    const std::size_t first = out.size();
    ranges.clear();
    for (int k = 1; k <= kStart; ++k) {
      const double ta = t0 + (t1 - t0) * (k - 1) / kStart, tb = t0 + (t1 - t0) * k / kStart;
      const gp_Pnt2d next = c.Value(tb);
      add_chords(c, ta, tb, prev, next, 0, eps, out, &ranges);
      prev = next;
    }
    ends.push_back(prev);
    // Each chord's finer chords, for the points of its tube.
    for (std::size_t i = first; i < out.size(); ++i) {
      UvSegment& s = out[i];
      if (!(s.reach > 2 * fine_eps)) continue;  // as fine already
      const std::array<double, 2>& r = ranges[i - first];
      s.fine_first = static_cast<int>(fine.size());
      add_chords(c, r[0], r[1], gp_Pnt2d(s.au, s.av), gp_Pnt2d(s.bu, s.bv), 0, fine_eps, fine,
                 nullptr);
      s.fine_count = static_cast<int>(fine.size()) - s.fine_first;
    }
    edge_tolerance.resize(out.size(), BRep_Tool::Tolerance(edge));
    fine_tolerance.resize(fine.size(), BRep_Tool::Tolerance(edge));
    degenerated.resize(out.size(), BRep_Tool::Degenerated(edge));
    fine_degenerated.resize(fine.size(), BRep_Tool::Degenerated(edge));
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
  // Near the boundary the classifier answers with the edges' 3D tolerances:
  // each chord's tube also holds its edge's tolerance, carried into (u, v).
  const GeomAdaptor_Surface surface(f.surface);
  // The face classifier is built with the face's tolerance as its (u, v)
  // tolerance: within it of the boundary it may answer ON.
  const double margin = 1e-7 * uv_size + 2 * face_tolerance + gap;
  auto widen = [&](UvSegment& s, double edge_tol, bool pole) {
    const double tolerance = std::max(edge_tol, face_tolerance);
    s.reach += margin + 2 * uv_reach(surface, s, pole, tolerance, kReachCap * uv_size);
  };
  for (std::size_t i = 0; i < out.size(); ++i) widen(out[i], edge_tolerance[i], degenerated[i]);
  poles.clear();
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (!degenerated[i]) continue;
    poles.push_back(out[i]);
    poles.back().reach += 2 * kReachCap * uv_size;
  }
  for (std::size_t i = 0; i < fine.size(); ++i) {
    widen(fine[i], fine_tolerance[i], fine_degenerated[i]);
  }
}

bool UvCells::near_pole(double u, double v) const {
  for (const UvSegment& s : poles) {
    if (point_segment(u, v, s) <= s.reach) return true;
  }
  return false;
}

UvState UvCells::state_at(double u, double v) const {
  if (nodes.empty()) return UvState::boundary;
  // Every representative (u + i Pu, v + j Pv) within the box and its margin:
  // a face's box may span more than one period (a thread winding twice).
  const double m = box_margin;
  const double first_u = u_period > 0 ? u - u_period * std::floor((u - (u0 - m)) / u_period) : u;
  const double first_v = v_period > 0 ? v - v_period * std::floor((v - (v0 - m)) / v_period) : v;
  UvState best = UvState::outside;
  for (double cu = first_u; cu <= u1 + m; cu += u_period) {
    for (double cv = first_v; cv <= v1 + m; cv += v_period) {
      const UvState s = state_in_box(cu, cv);
      if (s == UvState::inside) return s;
      if (s == UvState::boundary) best = s;
      if (!(v_period > 0)) break;
    }
    if (!(u_period > 0)) break;
  }
  return best;
}

UvState UvCells::state_in_box(double u, double v) const {
  if (u < u0 || u > u1 || v < v0 || v > v1) {  // beyond the box: out, unless in a tube
    const double m = box_margin;
    return u < u0 - m || u > u1 + m || v < v0 - m || v > v1 + m ? UvState::outside
                                                                : UvState::boundary;
  }
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
  const double eps = 1e-12 * scale * scale;
  for (int k = leaf.first; k < leaf.first + leaf.count; ++k) {
    const UvSegment& s = segments[segment_refs[k]];
    if (point_segment(u, v, s) > s.reach) {
      const int x = crossing(s, ru, rv, u, v, eps);
      if (x < 0) return UvState::boundary;  // through a chord's end
      inside = inside != (x == 1);
      continue;
    }
    // In the chord's tube: its finer chords (same ends) decide, unless the
    // point, or the reference, lies in one of their tubes.
    if (s.fine_count == 0) return UvState::boundary;
    for (int j = s.fine_first; j < s.fine_first + s.fine_count; ++j) {
      const UvSegment& t = fine[j];
      if (point_segment(u, v, t) <= t.reach || point_segment(ru, rv, t) <= t.reach) {
        return UvState::boundary;
      }
      const int x = crossing(t, ru, rv, u, v, eps);
      if (x < 0) return UvState::boundary;
      inside = inside != (x == 1);
    }
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
    const TopAbs_State state = c.Perform(gp_Pnt2d(u, v), Standard_False);
    if (state != TopAbs_IN && state != TopAbs_OUT) continue;
    Node& m = nodes[index];
    m.has_reference = true;
    m.reference_inside = state == TopAbs_IN;
    m.ref_u = u, m.ref_v = v;
    return;
  }
}

}  // namespace rdmesh::cad
