// A face's cells and triangles (face_tessellation.h).
#include "face_tessellation.h"

#include <GeomAdaptor_Surface.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <gp_Pnt2d.hxx>
#include <sstream>
#include <string>

#include "cad_model.h"
#include "cpu_time.h"
#include "rdmesh/errors.h"
#include "surface_evaluator.h"

namespace rdmesh::cad {
namespace {

constexpr double kMaxSpread = 0.16;        // rad: normals of a cell within this of their mean
constexpr double kMaxBend = 0.02;          // chord sagitta / cell extent
constexpr double kMaxSagitta = 1e-3;       // x model diagonal: largest chord sagitta
constexpr double kMaxCell = 0.25;          // x model diagonal: largest cell
constexpr double kBoundaryCell = 1.0 / 8;  // x face box diagonal: largest boundary cell
constexpr int kMaxDepth = 24;              // adaptive binary splits of one cell
constexpr double kConeFactor = 1.5, kConeMargin = 0.005;  // measured cone -> used cone
constexpr double kDeviationFactor = 2;                    // sampled deviation -> bound

struct Box2 {
  double u0, u1, v0, v1;
};

// Whether chord s's tube can meet cell r.
bool meets(const UvSegment& s, const Box2& r) {
  return std::min(s.au, s.bu) - s.reach <= r.u1 && r.u0 <= std::max(s.au, s.bu) + s.reach &&
         std::min(s.av, s.bv) - s.reach <= r.v1 && r.v0 <= std::max(s.av, s.bv) + s.reach;
}

Point3 unit_normal(const Point3& su, const Point3& sv) {
  const Point3 n = cross(su, sv);
  const double l = norm(n);
  if (!(l > 1e-12 * norm(su) * norm(sv)) || !(l > 0)) return {};
  return (1 / l) * n;
}

// S(u, v) and its unit normal; where the normal degenerates (a pole, a collapsed
// edge) the normal is taken a little way towards (uc, vc), where it is the limit
// normal of the region. Zero when it stays degenerate. Returns false when the
// normal at (u, v) itself degenerates.
bool sample(const SurfaceEvaluator& s, double u, double v, double uc, double vc, Point3& p,
            Point3& n) {
  Point3 su, sv;
  s.d1(u, v, p, su, sv);
  n = unit_normal(su, sv);
  if (squared_norm(n) > 0) return true;
  for (double step : {1e-6, 1e-3}) {
    Point3 q;
    s.d1(u + step * (uc - u), v + step * (vc - v), q, su, sv);
    n = unit_normal(su, sv);
    if (squared_norm(n) > 0) break;
  }
  return false;
}

// Angle between unit normals; 0 when either is degenerate (zero).
double angle(const Point3& a, const Point3& b) {
  if (squared_norm(a) == 0 || squared_norm(b) == 0) return 0;
  return std::acos(std::clamp(dot(a, b), -1.0, 1.0));
}

// Cut values forced in one parameter: the surface's C2 breaks (B-spline knots),
// then every interval longer than `longest` cut evenly.
std::vector<double> forced_cuts(const GeomAdaptor_Surface& s, bool u, double lo, double hi,
                                double longest) {
  std::vector<double> breaks{lo, hi};
  const int n = u ? s.NbUIntervals(GeomAbs_C2) : s.NbVIntervals(GeomAbs_C2);
  if (n > 1 && n < 512) {
    TColStd_Array1OfReal t(1, n + 1);
    if (u) {
      s.UIntervals(t, GeomAbs_C2);
    } else {
      s.VIntervals(t, GeomAbs_C2);
    }
    for (int i = 1; i <= n + 1; ++i) {
      if (t(i) > lo && t(i) < hi) breaks.push_back(t(i));
    }
  }
  std::sort(breaks.begin(), breaks.end());
  std::vector<double> cuts;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double a = breaks[i], b = breaks[i + 1];
    if (i > 0) cuts.push_back(a);
    const double n = std::ceil((b - a) / longest - 1e-9);  // NaN for a face of no width
    const int parts = n >= 1 && n < 1e6 ? static_cast<int>(n) : 1;
    for (int k = 1; k < parts; ++k) cuts.push_back(a + (b - a) * k / parts);
  }
  return cuts;
}

// A cell's 3 x 3 samples: [i][j] at u = u0, (u0 + u1) / 2, u1 and v likewise.
using Grid = std::array<std::array<SurfaceSample, 3>, 3>;
// Which samples of a Grid are already taken (a bit per [i][j], i * 3 + j).
using Known = unsigned;

class Builder {
 public:
  Builder(FacePatch& f, int face, const SurfaceEvaluator& s, double size,
          std::vector<SurfaceTriangle>& out, std::size_t max_nodes, const PrepDeadline& deadline)
      : f_(f),
        face_(face),
        s_(s),
        size_(size),
        max_nodes_(max_nodes),
        deadline_(deadline),
        out_(out) {
    planar_ = f.kind == SurfaceKind::plane;
    face_size_ = f.box.diagonal();
    boundary_segments(f, f.cells.segments, f.cells.fine, f.cells.poles);
    for (const UvSegment& seg : f.cells.segments) {
      f.cells.box_margin = std::max(f.cells.box_margin, seg.reach);
    }
    const GeomAdaptor_Surface a(f.surface, f.u0, f.u1, f.v0, f.v1);
    const double half_u = 0.5 * (f.u1 - f.u0), half_v = 0.5 * (f.v1 - f.v0);
    u_cuts_ = forced_cuts(a, true, f.u0, f.u1, a.IsUPeriodic() ? std::min(half_u, 0.8) : half_u);
    v_cuts_ = forced_cuts(a, false, f.v0, f.v1, a.IsVPeriodic() ? std::min(half_v, 0.8) : half_v);
  }

  void run() {
    UvCells& c = f_.cells;
    c.u0 = f_.u0, c.u1 = f_.u1, c.v0 = f_.v0, c.v1 = f_.v1;
    c.u_period = s_.u_period(), c.v_period = s_.v_period();
    c.nodes.assign(1, {});
    std::vector<int> all(c.segments.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    build(0, {f_.u0, f_.u1, f_.v0, f_.v1}, all, 0, Grid{}, 0);
  }

 private:
  // Splits node `index` (cell r) at `cut` along `axis`; both halves are built.
  // A cut through the middle hands each half the regular samples of r's grid
  // `g` that it shares (two of its three rows or columns).
  void split(int index, const Box2& r, int axis, double cut, const std::vector<int>& pieces,
             int depth, const Grid* g) {
    const int child = static_cast<int>(f_.cells.nodes.size());
    if (f_.cells.nodes.size() + 2 > max_nodes_) {
      throw InputError("face " + std::to_string(face_ + 1) +
                       ": following its surface needs more than " + std::to_string(max_nodes_) +
                       " cells (a surface far from its edges, as with a corrupt control point?)");
    }
    f_.cells.nodes.resize(child + 2);
    f_.cells.nodes[index].child = child;
    f_.cells.nodes[index].axis = static_cast<std::uint8_t>(axis);
    f_.cells.nodes[index].split = cut;
    Box2 lo = r, hi = r;
    (axis == 0 ? lo.u1 : lo.v1) = cut;
    (axis == 0 ? hi.u0 : hi.v0) = cut;
    Grid glo{}, ghi{};
    Known klo = 0, khi = 0;
    if (g) {
      // Half `h` (0: lo, 1: hi) takes the parent's lines h and h + 1 as its lines 0 and 2.
      auto take = [&](Grid& out, Known& known, int h) {
        for (int a = 0; a < 3; ++a) {
          for (int line = 0; line < 2; ++line) {
            const int pi = axis == 0 ? h + line : a, pj = axis == 0 ? a : h + line;
            const int ci = axis == 0 ? 2 * line : a, cj = axis == 0 ? a : 2 * line;
            if (!(*g)[pi][pj].regular) continue;
            out[ci][cj] = (*g)[pi][pj];
            known |= 1u << (ci * 3 + cj);
          }
        }
      };
      take(glo, klo, 0);
      take(ghi, khi, 1);
    }
    build(child, lo, pieces, depth, glo, klo);
    build(child + 1, hi, pieces, depth, ghi, khi);
  }

  static bool forced(const std::vector<double>& cuts, double lo, double hi, double& cut) {
    const double mid = 0.5 * (lo + hi);
    bool found = false;
    for (double c : cuts) {
      if (c > lo && c < hi && (!found || std::fabs(c - mid) < std::fabs(cut - mid))) {
        cut = c;
        found = true;
      }
    }
    return found;
  }

  void build(int index, const Box2& r, const std::vector<int>& parent_pieces, int depth, Grid g,
             Known known) {
    deadline_.check();
    std::vector<int> pieces;  // the boundary chords whose tubes meet the cell
    for (int p : parent_pieces) {
      if (meets(f_.cells.segments[p], r)) pieces.push_back(p);
    }
    double cut = 0;
    if (forced(u_cuts_, r.u0, r.u1, cut)) return split(index, r, 0, cut, pieces, depth, nullptr);
    if (forced(v_cuts_, r.v0, r.v1, cut)) return split(index, r, 1, cut, pieces, depth, nullptr);
    UvState state = UvState::boundary;
    const double um = 0.5 * (r.u0 + r.u1), vm = 0.5 * (r.v0 + r.v1);
    if (pieces.empty()) {  // no boundary in the cell: all of it is in, or out
      // (the point itself: no shift by periods, which state_at() tries later)
      const TopAbs_State s = f_.classifier->Perform(gp_Pnt2d(um, vm), Standard_False);
      if (s == TopAbs_IN) state = UvState::inside;
      if (s == TopAbs_OUT) state = UvState::outside;
    }
    f_.cells.nodes[index].state = state;
    if (state == UvState::outside) return;
    // 3 x 3 samples: corners, edge midpoints, centre.
    // Normals at singular samples (poles, collapsed edges) are kept for the
    // triangles but left out of the split criteria (o): near such points the
    // limit normal may flip from one sample to the next.
    const double us[3] = {r.u0, um, r.u1}, vs[3] = {r.v0, vm, r.v1};
    Point3 p[3][3], n[3][3], o[3][3];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        SurfaceSample& x = g[i][j];
        if (!(known & (1u << (i * 3 + j)))) {
          x.regular = sample(s_, us[i], vs[j], um, vm, x.p, x.n);
        }
        p[i][j] = x.p, n[i][j] = x.n;
        o[i][j] = x.regular ? x.n : Point3{};
      }
    }
    double ext_u = 0, ext_v = 0, turn_u = 0, turn_v = 0, spread = 0;
    Point3 mean{};
    for (int k = 0; k < 3; ++k) {
      ext_u = std::max(ext_u, distance(p[0][k], p[1][k]) + distance(p[1][k], p[2][k]));
      ext_v = std::max(ext_v, distance(p[k][0], p[k][1]) + distance(p[k][1], p[k][2]));
      turn_u = std::max(turn_u, angle(o[0][k], o[2][k]));
      turn_v = std::max(turn_v, angle(o[k][0], o[k][2]));
      for (int j = 0; j < 3; ++j) mean = mean + o[k][j];
    }
    if (!planar_ && norm(mean) > 0) {
      const Point3 axis = (1 / norm(mean)) * mean;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) spread = std::max(spread, angle(o[i][j], axis));
      }
    }
    // Sagittas of the chords along u and along v (the surface's bend, in any direction).
    double sag_u = 0, sag_v = 0;
    for (int k = 0; k < 3; ++k) {
      sag_u = std::max(sag_u, distance(p[1][k], 0.5 * (p[0][k] + p[2][k])));
      sag_v = std::max(sag_v, distance(p[k][1], 0.5 * (p[k][0] + p[k][2])));
    }
    const double extent = std::max(ext_u, ext_v), sagitta = std::max(sag_u, sag_v);
    const bool turns = spread > kMaxSpread;
    const bool bends = sagitta > kMaxBend * extent || sagitta > kMaxSagitta * size_;
    const bool large = extent > kMaxCell * size_ ||
                       (state == UvState::boundary && extent > kBoundaryCell * face_size_);
    if (depth < kMaxDepth && (turns || bends || large)) {
      int axis = ext_u >= ext_v ? 0 : 1;  // large: halve the longer side
      if (bends) axis = sag_u >= sag_v ? 0 : 1;
      if (turns) axis = turn_u >= turn_v ? 0 : 1;
      // Never a side already a thousand times shorter than the other.
      if (1000 * (axis == 0 ? ext_u : ext_v) < (axis == 0 ? ext_v : ext_u)) axis = 1 - axis;
      return split(index, r, axis, axis == 0 ? um : vm, pieces, depth + 1, &g);
    }
    if (state == UvState::boundary) {
      f_.cells.set_boundary_leaf(index, r.u0, r.u1, r.v0, r.v1, pieces, *f_.classifier);
    }
    // A leaf: two triangles split along the (u0, v0)-(u1, v1) diagonal.
    const double cu[2] = {r.u0, r.u1}, cv[2] = {r.v0, r.v1};
    const int tri[2][3][2] = {{{0, 0}, {1, 0}, {1, 1}}, {{0, 0}, {1, 1}, {0, 1}}};
    // The grid samples at their edges' midpoints, edge (k, k + 1) for k = 0, 1, 2.
    const SurfaceSample mids[2][3] = {{g[1][0], g[2][1], g[1][1]}, {g[1][1], g[1][2], g[0][1]}};
    for (int c = 0; c < 2; ++c) {
      const auto& corners = tri[c];
      SurfaceTriangle t;
      t.face = face_;
      for (int k = 0; k < 3; ++k) {
        const int i = corners[k][0], j = corners[k][1];
        t.uv[k][0] = cu[i], t.uv[k][1] = cv[j];
        t.p[k] = p[2 * i][2 * j];
        t.n[k] = n[2 * i][2 * j];
      }
      measure_triangle(s_, t, mids[c]);
      out_.push_back(t);
    }
  }

  FacePatch& f_;
  int face_;
  const SurfaceEvaluator& s_;
  double size_, face_size_ = 0;
  std::size_t max_nodes_;
  const PrepDeadline& deadline_;
  bool planar_ = false;
  std::vector<double> u_cuts_, v_cuts_;
  std::vector<SurfaceTriangle>& out_;
};

}  // namespace

PrepDeadline PrepDeadline::starting_now(double seconds) {
  PrepDeadline d;
  d.seconds = seconds;
  d.start_cpu = thread_cpu_seconds();
  return d;
}

void PrepDeadline::check() const {
  if (seconds <= 0 || (calls_++ & 31u) != 0) return;
  if (thread_cpu_seconds() - start_cpu <= seconds) return;
  std::ostringstream o;
  o << "preparing the model did not finish within " << seconds
    << " s of computing (malformed geometry: surfaces far from their edges or huge "
       "tolerances?)";
  throw InputError(o.str());
}

Box3 triangle_box(const SurfaceTriangle& t, double r) {
  Box3 b{t.p[0], t.p[0]};
  for (int k = 1; k < 3; ++k) {
    b.lo = {std::min(b.lo.x, t.p[k].x), std::min(b.lo.y, t.p[k].y), std::min(b.lo.z, t.p[k].z)};
    b.hi = {std::max(b.hi.x, t.p[k].x), std::max(b.hi.y, t.p[k].y), std::max(b.hi.z, t.p[k].z)};
  }
  b.lo = b.lo - Point3{r, r, r};
  b.hi = b.hi + Point3{r, r, r};
  return b;
}

void measure_triangle(const SurfaceEvaluator& s, SurfaceTriangle& t,
                      const SurfaceSample* midpoints) {
  const double uc = (t.uv[0][0] + t.uv[1][0] + t.uv[2][0]) / 3;
  const double vc = (t.uv[0][1] + t.uv[1][1] + t.uv[2][1]) / 3;
  Point3 normals[7];
  int count = 0;
  double dev = 0;
  auto measure = [&](double u, double v, const Point3& flat, const SurfaceSample* known) {
    Point3 p;
    if (known && known->regular) {
      p = known->p, normals[count++] = known->n;
    } else {
      sample(s, u, v, uc, vc, p, normals[count++]);
    }
    dev = std::max(dev, distance(p, flat));
  };
  for (int k = 0; k < 3; ++k) {
    const int l = (k + 1) % 3;
    measure(0.5 * (t.uv[k][0] + t.uv[l][0]), 0.5 * (t.uv[k][1] + t.uv[l][1]),
            0.5 * (t.p[k] + t.p[l]), midpoints ? &midpoints[k] : nullptr);
  }
  measure(uc, vc, (1.0 / 3) * (t.p[0] + t.p[1] + t.p[2]), nullptr);
  for (int k = 0; k < 3; ++k) {
    if (squared_norm(t.n[k]) == 0) {  // a pole: the limit normal from inside
      Point3 p;
      sample(s, t.uv[k][0], t.uv[k][1], uc, vc, p, t.n[k]);
    }
    normals[count++] = t.n[k];
  }
  t.deviation = kDeviationFactor * dev;
  bool degenerate = false;
  Point3 mean{};
  for (int k = 0; k < count; ++k) {
    mean = mean + normals[k];
    degenerate = degenerate || squared_norm(normals[k]) == 0;
  }
  const Point3 flat = cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
  const double longest = std::max({squared_norm(t.p[1] - t.p[0]), squared_norm(t.p[2] - t.p[1]),
                                   squared_norm(t.p[0] - t.p[2])});
  const double mean_length = norm(mean);
  if (norm(flat) > 1e-9 * longest) {
    t.axis = (1 / norm(flat)) * flat;
    if (dot(t.axis, mean) < 0) t.axis = -1.0 * t.axis;
  } else {  // a triangle collapsed at a pole: the mean normal
    t.axis = mean_length > 0 ? (1 / mean_length) * mean : Point3{0, 0, 1};
  }
  double alpha = 0;
  for (int k = 0; k < count; ++k) alpha = std::max(alpha, angle(normals[k], t.axis));
  const double cone = kConeFactor * alpha + kConeMargin;
  t.sin_cone = degenerate || cone >= 0.5 * M_PI ? 1 : std::sin(cone);
}

void tessellate_face(FacePatch& f, int face, const SurfaceEvaluator& surface, double size,
                     std::vector<SurfaceTriangle>& out, std::size_t max_nodes,
                     const PrepDeadline& deadline) {
  Builder(f, face, surface, size, out, max_nodes, deadline).run();
}

}  // namespace rdmesh::cad
