// CadOracle queries. OpenCASCADE's intersectors and classifiers keep state, so
// each thread lazily builds its own per face / per solid and keeps them in a
// small per-thread cache keyed by the oracle's serial number.
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <Bnd_BoundSortBox.hxx>
#include <ElSLib.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_Line.hxx>
#include <IntCurveSurface_HInter.hxx>
#include <IntCurveSurface_IntersectionPoint.hxx>
#include <IntCurveSurface_ThePolygonOfHInter.hxx>
#include <IntCurveSurface_ThePolyhedronOfHInter.hxx>
#include <IntCurvesFace_Intersector.hxx>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <gp_Lin.hxx>
#include <gp_Pnt2d.hxx>

#include "cad_model.h"

namespace rdmesh {
namespace {

using cad::describe;

gp_Pnt to_gp(const Point3& p) { return {p.x, p.y, p.z}; }
Point3 to_point(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

// A sampled free-form face: its polyhedron seeds IntCurveSurface_HInter.
struct SampledFace {
  Handle(GeomAdaptor_Surface) surface;
  std::unique_ptr<IntCurveSurface_ThePolyhedronOfHInter> polyhedron;
  Bnd_BoundSortBox boxes;
};

struct ThreadCache {
  std::uint64_t serial = 0;
  std::vector<std::unique_ptr<IntCurvesFace_Intersector>> faces;
  std::vector<std::unique_ptr<SampledFace>> sampled;
  std::vector<std::pair<double, int>> candidates;  // (box entry, face index), reused
};

ThreadCache& cache_for(std::uint64_t serial, std::size_t faces) {
  thread_local std::array<ThreadCache, 4> caches;
  thread_local std::size_t next = 0;
  for (ThreadCache& c : caches) {
    if (c.serial == serial) return c;
  }
  ThreadCache& c = caches[next];
  next = (next + 1) % caches.size();
  c.serial = serial;
  c.faces.clear();
  c.faces.resize(faces);
  c.sampled.clear();
  c.sampled.resize(faces);
  return c;
}

std::atomic<std::uint64_t> next_serial{1};

// Entry parameter of ray a + t d (t in [0, 1]) into the box, or -1 when it misses.
double box_entry(const Point3& a, const Point3& d, const Box3& box) {
  double t0 = 0, t1 = 1;
  const double o[3] = {a.x, a.y, a.z}, v[3] = {d.x, d.y, d.z};
  const double lo[3] = {box.lo.x, box.lo.y, box.lo.z}, hi[3] = {box.hi.x, box.hi.y, box.hi.z};
  for (int k = 0; k < 3; ++k) {
    if (v[k] == 0) {
      if (o[k] < lo[k] || o[k] > hi[k]) return -1;
      continue;
    }
    double ta = (lo[k] - o[k]) / v[k], tb = (hi[k] - o[k]) / v[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return -1;
  }
  return t0;
}

// Ray directions for locate(): generic (no axis or diagonal alignment).
constexpr Point3 kRays[3] = {{0.8017837257372732, 0.5345224838248488, 0.2672612419124244},
                             {-0.3162277660168379, 0.1825741858350554, 0.9309493362512627},
                             {0.2357022603955158, -0.9428090415820634, 0.2357022603955158}};

[[noreturn]] void rethrow_occt(const Standard_Failure& e, const char* query) {
  throw OracleError(std::string("OpenCASCADE failed in ") + query + ": " + describe(e));
}

}  // namespace

CadOracle::CadOracle(std::unique_ptr<Model> model)
    : model_(std::move(model)), serial_(next_serial.fetch_add(1)) {}

CadOracle::~CadOracle() = default;

Box3 CadOracle::bounding_box() const { return model_->box; }
std::vector<SubdomainInfo> CadOracle::subdomains() const { return model_->subdomains; }
std::vector<PatchInfo> CadOracle::patches() const { return model_->patches; }
double CadOracle::tolerance() const { return model_->tolerance; }
std::vector<CornerInfo> CadOracle::corners() const { return model_->corners; }
std::vector<CurveInfo> CadOracle::curves() const { return model_->curve_infos; }
int CadOracle::input_solids() const { return model_->input_solids; }
const std::vector<std::string>& CadOracle::log() const { return model_->log; }

const Curve& CadOracle::curve(CurveId id) const {
  if (id.value < 1 || id.value > static_cast<int>(model_->curves.size())) {
    throw OracleError("CAD oracle: no curve " + std::to_string(id.value));
  }
  return *model_->curves[id.value - 1];
}

std::vector<Point3> CadOracle::initial_points(PatchId patch) const {
  if (patch.value < 1 || patch.value > static_cast<int>(model_->seeds.size())) return {};
  return model_->seeds[patch.value - 1];
}

void CadOracle::plane_hit(const cad::FacePatch& f, int index, const Point3& a, const Point3& d,
                          double len, std::optional<RayHit>& best) const {
  const gp_Ax3& ax = f.plane->Position();
  const gp_Dir nd = ax.XDirection().Crossed(ax.YDirection());  // du x dv
  const Point3 n{nd.X(), nd.Y(), nd.Z()};
  const gp_Pnt& o = ax.Location();
  const double denom = dot(n, d);
  if (denom == 0) return;
  const double t = dot(n, Point3{o.X(), o.Y(), o.Z()} - a) / denom;
  if (!(t >= 0 && t <= 1) || (best && t * len >= best->distance)) return;
  const Point3 x = a + t * d;
  double u, v;
  ElSLib::Parameters(*f.plane, to_gp(x), u, v);
  const TopAbs_State state = f.classifier->Perform(gp_Pnt2d(u, v));
  if (state != TopAbs_IN && state != TopAbs_ON) return;
  RayHit h;
  h.distance = t * len;
  h.face = index;
  h.point = x;
  h.tangent = state == TopAbs_ON;
  h.cosine = denom / len * (f.face.Orientation() == TopAbs_REVERSED ? -1 : 1);
  best = h;
}

void CadOracle::quadric_hit(const cad::FacePatch& f, int index, const Point3& a, const Point3& d,
                            double len, std::optional<RayHit>& best) const {
  const double upper = best ? best->distance : len;
  if (!(upper > 1e-12 * len)) return;
  const Handle(Geom_Line) line = new Geom_Line(to_gp(a), gp_Dir(d.x, d.y, d.z));
  const Handle(GeomAdaptor_Curve) curve = new GeomAdaptor_Curve(line, 0.0, upper);
  const Handle(GeomAdaptor_Surface) surface =
      new GeomAdaptor_Surface(f.surface, f.u0, f.u1, f.v0, f.v1);
  IntCurveSurface_HInter inter;
  if (f.quadric) {
    inter.Perform(curve, surface);
  } else {
    // Free-form face: sample it once per thread, then reuse the polyhedron.
    ThreadCache& cache = cache_for(serial_, model_->faces.size());
    std::unique_ptr<SampledFace>& sf = cache.sampled[index];
    if (!sf) {
      sf = std::make_unique<SampledFace>();
      sf->surface = surface;
      const int nu =
          std::clamp(surface->NbUIntervals(GeomAbs_C2) * (surface->UDegree() + 1), 10, 50);
      const int nv =
          std::clamp(surface->NbVIntervals(GeomAbs_C2) * (surface->VDegree() + 1), 10, 50);
      sf->polyhedron = std::make_unique<IntCurveSurface_ThePolyhedronOfHInter>(
          sf->surface, nu, nv, f.u0, f.v0, f.u1, f.v1);
      sf->polyhedron->FillBounding();
      sf->boxes.Initialize(sf->polyhedron->Bounding(), sf->polyhedron->ComponentsBounding());
    }
    const IntCurveSurface_ThePolygonOfHInter polygon(curve, 0.0, upper, 3);
    inter.Perform(curve, polygon, sf->surface, *sf->polyhedron, sf->boxes);
  }
  if (!inter.IsDone()) return;
  for (int k = 1; k <= inter.NbPoints(); ++k) {
    const IntCurveSurface_IntersectionPoint& ip = inter.Point(k);
    const double w = ip.W();
    if (w < 0 || w > len || (best && w >= best->distance)) continue;
    const TopAbs_State state = f.classifier->Perform(gp_Pnt2d(ip.U(), ip.V()));
    if (state != TopAbs_IN && state != TopAbs_ON) continue;
    RayHit h;
    h.distance = w;
    h.face = index;
    h.point = to_point(ip.Pnt());
    h.tangent = ip.Transition() == IntCurveSurface_Tangent || state == TopAbs_ON;
    gp_Pnt p;
    gp_Vec du, dv;
    f.surface->D1(ip.U(), ip.V(), p, du, dv);
    gp_Vec n = du.Crossed(dv);
    if (f.face.Orientation() == TopAbs_REVERSED) n.Reverse();
    const double nn = n.Magnitude();
    h.cosine = nn > 0 ? (n.X() * d.x + n.Y() * d.y + n.Z() * d.z) / (nn * len) : 0.0;
    best = h;
  }
}

std::optional<CadOracle::RayHit> CadOracle::first_hit(const Point3& a, const Point3& d) const {
  const Model& m = *model_;
  const double len = norm(d);
  if (!(len > 0)) return std::nullopt;
  ThreadCache& cache = cache_for(serial_, m.faces.size());
  std::vector<std::pair<double, int>>& cand = cache.candidates;
  cand.clear();
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    const double t = box_entry(a, d, m.faces[i].box);
    if (t >= 0) cand.emplace_back(t, static_cast<int>(i));
  }
  std::sort(cand.begin(), cand.end());
  const gp_Lin line(to_gp(a), gp_Dir(d.x, d.y, d.z));
  std::optional<RayHit> best;
  for (const auto& [entry, i] : cand) {
    if (best && entry * len > best->distance) break;  // boxes sorted by entry
    if (m.faces[i].plane) {
      plane_hit(m.faces[i], i, a, d, len, best);
      continue;
    }
    if (m.faces[i].quadric || m.faces[i].spline) {
      try {
        quadric_hit(m.faces[i], i, a, d, len, best);
        continue;
      } catch (const Standard_Failure&) {
        // fall through to the general intersector
      }
    }
    std::unique_ptr<IntCurvesFace_Intersector>& x = cache.faces[i];
    if (!x) x = std::make_unique<IntCurvesFace_Intersector>(m.faces[i].face, 0.1 * m.tolerance);
    const double upper = best ? best->distance : len;
    if (!(upper > 1e-12 * len)) continue;  // a hit at the start point already
    try {
      x->Perform(line, 0.0, upper);
    } catch (const Standard_Failure&) {
      continue;  // a degenerate sub-problem of this face: no crossing found there
    }
    if (!x->IsDone()) continue;
    for (int k = 1; k <= x->NbPnt(); ++k) {
      const double w = x->WParameter(k);
      if (w < 0 || w > len || (best && w >= best->distance)) continue;
      RayHit h;
      h.distance = w;
      h.face = i;
      h.point = to_point(x->Pnt(k));
      h.tangent = x->Transition(k) == IntCurveSurface_Tangent || x->State(k) == TopAbs_ON;
      gp_Pnt p;
      gp_Vec du, dv;
      m.faces[i].surface->D1(x->UParameter(k), x->VParameter(k), p, du, dv);
      gp_Vec n = du.Crossed(dv);
      if (m.faces[i].face.Orientation() == TopAbs_REVERSED) n.Reverse();
      const double nn = n.Magnitude();
      h.cosine = nn > 0 ? (n.X() * d.x + n.Y() * d.y + n.Z() * d.z) / (nn * len) : 0.0;
      best = h;
    }
  }
  return best;
}

SubdomainId CadOracle::locate(const Point3& p) const {
  const Model& m = *model_;
  if (!m.box.contains(p)) return kOutside;
  const double reach = 2 * m.box.diagonal();
  try {
    SubdomainId answer = kOutside;
    for (const Point3& dir : kRays) {
      const std::optional<RayHit> h = first_hit(p, reach * dir);
      if (!h) return kOutside;  // the ray leaves the domain without crossing a face
      const cad::FacePatch& f = m.faces[h->face];
      // The ray leaves the side the normal points out of when it goes along the normal.
      answer = h->cosine > 0 ? f.outward_of : f.inward_of;
      if (!h->tangent && std::fabs(h->cosine) > 1e-3) return answer;
    }
    return answer;  // every ray grazed: keep the last answer
  } catch (const Standard_Failure& e) {
    rethrow_occt(e, "locate");
  }
}

std::optional<SurfaceHit> CadOracle::intersect(const Point3& a, const Point3& b) const {
  const Model& m = *model_;
  const Point3 d = b - a;
  const double len = norm(d);
  if (!(len > 0) || !std::isfinite(len)) return std::nullopt;
  try {
    const std::optional<RayHit> h = first_hit(a, d);
    if (h && !(h->tangent && std::fabs(h->cosine) < 1e-6)) {
      return SurfaceHit{h->point, m.patches[h->face].id};
    }
  } catch (const Standard_Failure& e) {
    rethrow_occt(e, "intersect");
  }
  // No transversal crossing found (a grazing segment, an edge): bracket the label change.
  const SubdomainId la = locate(a), lb = locate(b);
  if (la == lb) return std::nullopt;
  double lo = 0, hi = 1;
  SubdomainId lhi = lb;
  for (int it = 0; it < 200 && (hi - lo) * len > m.tolerance; ++it) {
    const double mid = 0.5 * (lo + hi);
    const SubdomainId l = locate(a + mid * d);
    if (l == la) {
      lo = mid;
    } else {
      hi = mid, lhi = l;
    }
  }
  const Point3 x = a + (0.5 * (lo + hi)) * d;
  const SubdomainId s0 = std::min(la, lhi), s1 = std::max(la, lhi);
  std::optional<PatchId> fallback;
  for (std::size_t i = 0; i < m.patches.size(); ++i) {
    const PatchInfo& p = m.patches[i];
    if (p.side_a != s0 || p.side_b != s1) continue;
    if (m.faces[i].box.contains(x)) return SurfaceHit{x, p.id};
    if (!fallback) fallback = p.id;
  }
  if (!fallback) return std::nullopt;
  return SurfaceHit{x, *fallback};
}

std::optional<Point3> CadOracle::project(const Point3& p, PatchId patch) const {
  const Model& m = *model_;
  if (patch.value < 1 || patch.value > static_cast<int>(m.faces.size())) return std::nullopt;
  const cad::FacePatch& f = m.faces[patch.value - 1];
  try {
    GeomAPI_ProjectPointOnSurf proj(to_gp(p), f.surface, f.u0, f.u1, f.v0, f.v1);
    if (proj.NbPoints() > 0) {
      double u, v;
      proj.LowerDistanceParameters(u, v);
      const TopAbs_State s = f.classifier->Perform(gp_Pnt2d(u, v));
      if (s == TopAbs_IN || s == TopAbs_ON) return to_point(proj.NearestPoint());
    }
    // The foot point is outside the trimmed face: the closest point is on its boundary.
    BRepExtrema_DistShapeShape dist(BRepBuilderAPI_MakeVertex(to_gp(p)).Vertex(), f.face);
    if (dist.IsDone() && dist.NbSolution() > 0) return to_point(dist.PointOnShape2(1));
  } catch (const Standard_Failure&) {
    return std::nullopt;  // "does not converge"
  }
  return std::nullopt;
}

double CadOracle::exact_volume(SubdomainId id) const {
  double v = 0;
  try {
    for (const cad::SolidPiece& piece : model_->pieces) {
      if (id != kOutside && piece.id != id) continue;
      GProp_GProps props;
      BRepGProp::VolumeProperties(piece.solid, props);
      v += props.Mass();
    }
  } catch (const Standard_Failure& e) {
    rethrow_occt(e, "exact_volume");
  }
  return v;
}

std::unique_ptr<CadOracle> load_cad_file(const std::string& path, const CadOptions& options) {
  cad::ReadShape read = cad::read_shape(path, options);
  return std::make_unique<CadOracle>(cad::build_model(std::move(read), path));
}

}  // namespace rdmesh
