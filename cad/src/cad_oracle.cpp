// CadOracle queries: the nearest crossing along a segment (face_intersector.h)
// found through the triangle tree, locate() by rays, intersect() with its
// bisection fallback, project() (face_projection.h). OpenCASCADE's stateful
// objects live in per-thread caches (thread_state.h).
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <GeomLProp_SLProps.hxx>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "cad_model.h"
#include "face_intersector.h"
#include "face_projection.h"
#include "isolated_read.h"
#include "rdmesh/box_tree.h"
#include "thread_state.h"

namespace rdmesh {
namespace {

using cad::describe;

std::atomic<std::uint64_t> next_serial{1};

// Entry parameter of ray a + t d (t in [0, 1]) into the box, or -1 when it misses.
// Where segment a + t d, t in [0, 1], enters a box: its t, or -1 when it
// misses the box. The reciprocal of d is computed once per segment, since one
// segment meets many boxes of the candidate tree.
class BoxEntry {
 public:
  BoxEntry(const Point3& a, const Point3& d) : o_{a.x, a.y, a.z} {
    const double v[3] = {d.x, d.y, d.z};
    for (int k = 0; k < 3; ++k) {
      inv_[k] = 1.0 / v[k];  // +-inf along an axis the segment does not move along
      neg_[k] = std::signbit(inv_[k]);
    }
  }
  // Branch-free slabs: the near and far planes are picked by the direction's
  // sign once. Along a flat axis the products are -inf/+inf (the start inside
  // or outside the slab) or NaN (the start on a plane), and max/min with the
  // running bound first drop a NaN, so the slab is then no constraint.
  double operator()(const Box3& box) const {
    const double lo[3] = {box.lo.x, box.lo.y, box.lo.z}, hi[3] = {box.hi.x, box.hi.y, box.hi.z};
    double t0 = 0, t1 = 1;
    for (int k = 0; k < 3; ++k) {
      const double near = neg_[k] ? hi[k] : lo[k], far = neg_[k] ? lo[k] : hi[k];
      t0 = std::max(t0, (near - o_[k]) * inv_[k]);
      t1 = std::min(t1, (far - o_[k]) * inv_[k]);
    }
    return t0 <= t1 ? t0 : -1;
  }

 private:
  double o_[3], inv_[3];
  bool neg_[3];
};

// Ray directions for locate(): generic (no axis or diagonal alignment).
constexpr Point3 kRays[3] = {{0.8017837257372732, 0.5345224838248488, 0.2672612419124244},
                             {-0.3162277660168379, 0.1825741858350554, 0.9309493362512627},
                             {0.2357022603955158, -0.9428090415820634, 0.2357022603955158}};

[[noreturn]] void rethrow_occt(const Standard_Failure& e, const char* query) {
  throw OracleError(std::string("OpenCASCADE failed in ") + query + ": " + describe(e));
}

// Segment [a, b] within the model box (every face lies in it), and how far
// along [a, b] its start lies. Computed from the end nearer the box along the
// unit direction: a Voronoi ray may reach 1e20, and coordinates that far from
// the box carry no digits near it.
struct Clipped {
  Point3 a, b;
  double offset = 0;
};
std::optional<Clipped> clip_to_box(const Box3& box, const Point3& a, const Point3& b) {
  const Point3 d = b - a;
  const double len = norm(d);
  if (!(len > 0) || !std::isfinite(len)) return std::nullopt;
  const bool from_a = squared_distance(box, a) <= squared_distance(box, b);
  const Point3 o = from_a ? a : b, dir = (from_a ? 1 / len : -1 / len) * d;
  double s0 = 0, s1 = len;  // o + s dir, s in [s0, s1], lies in the box
  if (!clip_line(o, dir, box, s0, s1)) return std::nullopt;
  const Point3 p0 = o + s0 * dir, p1 = o + s1 * dir;
  if (from_a) return Clipped{p0, p1, s0};
  return Clipped{p1, p0, len - s1};
}

// The first crossing of segment [a, b] with a face: the candidates whose boxes
// the segment meets, nearest box first, until none can be nearer. Its distance
// is from a.
std::optional<cad::RayHit> first_hit(const CadOracle::Model& m, std::uint64_t serial,
                                     const Point3& a, const Point3& b) {
  const std::optional<Clipped> c = clip_to_box(m.box, a, b);
  if (!c || !m.occupied.may_meet(c->a, c->b)) return std::nullopt;
  const Point3 d = c->b - c->a;
  const double len = norm(d);
  if (!(len > 0)) return std::nullopt;
  cad::RayQuery query(m, cad::thread_state(m, serial), c->a, (1 / len) * d, len);
  double bound = query.reach();
  const BoxEntry entry(c->a, d);
  m.candidate_tree.nearest(
      [&](const Box3& box) {
        const double t = entry(box);
        return t < 0 ? std::numeric_limits<double>::infinity() : t * len;
      },
      [&](int t, double& reach) {
        query.visit(t);
        reach = query.reach();
      },
      bound);
  std::optional<cad::RayHit> h = query.best();
  if (h) h->distance += c->offset;
  return h;
}

// The label of a segment's start, read off its first crossing: the segment
// leaves the side the normal points out of when it goes along the normal.
SubdomainId side_of_start(const CadOracle::Model& m, const cad::RayHit& h) {
  const cad::FacePatch& f = m.faces[h.face];
  return h.cosine > 0 ? f.outward_of : f.inward_of;
}

}  // namespace

CadOracle::CadOracle(std::unique_ptr<Model> model)
    : model_(std::move(model)), serial_(next_serial.fetch_add(1)) {}

CadOracle::~CadOracle() = default;

Box3 CadOracle::bounding_box() const { return model_->box; }
std::vector<SubdomainInfo> CadOracle::subdomains() const { return model_->subdomains; }
std::vector<PatchInfo> CadOracle::patches() const { return model_->patches; }
double CadOracle::tolerance() const { return model_->tolerance; }
std::vector<CornerInfo> CadOracle::corners() const { return model_->features.corners(); }
std::vector<CurveInfo> CadOracle::curves() const { return model_->features.curves(); }
const Curve& CadOracle::curve(CurveId id) const { return model_->features.curve(id); }
int CadOracle::input_solids() const { return model_->input_solids; }
const std::vector<std::string>& CadOracle::log() const { return model_->log; }
const std::vector<std::string>& CadOracle::warnings() const { return model_->warnings; }

std::string CadOracle::patch_color(PatchId id) const {
  const auto i = static_cast<std::size_t>(id.value - 1);
  return id.value >= 1 && i < model_->patch_colors.size() ? model_->patch_colors[i] : std::string();
}

std::vector<Point3> CadOracle::initial_points(PatchId patch) const {
  return model_->features.initial_points(patch);
}

std::optional<CadOracle::Crossing> CadOracle::first_crossing(const Point3& a,
                                                             const Point3& b) const {
  try {
    const std::optional<cad::RayHit> h = first_hit(*model_, serial_, a, b);
    if (!h) return std::nullopt;
    return Crossing{h->point, model_->patches[h->face].id, h->distance, h->cosine, h->tangent};
  } catch (const Standard_Failure& e) {
    rethrow_occt(e, "first_crossing");
  }
}

Located CadOracle::locate(const Point3& p, const std::optional<LocateHint>& hint) const {
  const Model& m = *model_;
  if (!m.box.contains(p)) return {kOutside, std::nullopt};
  try {
    if (hint) {
      // The crossing nearest p on [p, known] is the last one on the way to p.
      const std::optional<cad::RayHit> h = first_hit(m, serial_, p, hint->point);
      if (!h) return {hint->label, std::nullopt};
      if (!h->tangent && std::fabs(h->cosine) > 1e-3) {
        return {side_of_start(m, *h), SurfaceHit{h->point, m.patches[h->face].id}};
      }
      // A grazing crossing: cast the rays as without a hint.
    }
    const double reach = 2 * m.box.diagonal();
    SubdomainId answer = kOutside;
    for (const Point3& dir : kRays) {
      const std::optional<cad::RayHit> h = first_hit(m, serial_, p, p + reach * dir);
      if (!h) return {kOutside, std::nullopt};  // the ray leaves the domain without crossing a face
      answer = side_of_start(m, *h);
      if (!h->tangent && std::fabs(h->cosine) > 1e-3) return {answer, std::nullopt};
    }
    return {answer, std::nullopt};  // every ray grazed: keep the last answer
  } catch (const Standard_Failure& e) {
    rethrow_occt(e, "locate");
  }
}

std::optional<SurfaceHit> CadOracle::intersect(const Point3& a, const Point3& b) const {
  const Model& m = *model_;
  // Everything happens on the part of [a, b] in the model box (see clip_to_box).
  const std::optional<Clipped> c = clip_to_box(m.box, a, b);
  if (!c) return std::nullopt;  // both ends outside the box, hence outside the domain
  const Point3 ca = c->a, d = c->b - c->a;
  const double len = norm(d);
  try {
    const std::optional<cad::RayHit> h = first_hit(m, serial_, ca, c->b);
    if (h && !(h->tangent && std::fabs(h->cosine) < 1e-6)) {
      return SurfaceHit{h->point, m.patches[h->face].id};
    }
  } catch (const Standard_Failure& e) {
    rethrow_occt(e, "intersect");
  }
  // No transversal crossing found (a grazing segment, an edge): bracket the label change.
  const SubdomainId la = locate(ca).label, lb = locate(c->b).label;
  if (la == lb) return std::nullopt;
  double lo = 0, hi = 1;
  SubdomainId lhi = lb;
  for (int it = 0; it < 200 && (hi - lo) * len > m.tolerance; ++it) {
    const double mid = 0.5 * (lo + hi);
    const SubdomainId l = locate(ca + mid * d).label;
    if (l == la) {
      lo = mid;
    } else {
      hi = mid, lhi = l;
    }
  }
  const Point3 x = ca + (0.5 * (lo + hi)) * d;
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
  try {
    return cad::project_on_face(m, cad::thread_state(m, serial_), patch.value - 1, p);
  } catch (const Standard_Failure&) {
    return std::nullopt;  // "does not converge"
  }
}

std::optional<double> CadOracle::curvature(const Point3& p, PatchId patch) const {
  const Model& m = *model_;
  if (patch.value < 1 || patch.value > static_cast<int>(m.faces.size())) return std::nullopt;
  const cad::FacePatch& f = m.faces[static_cast<std::size_t>(patch.value) - 1];
  switch (f.kind) {
    case cad::SurfaceKind::plane:
      return 0.0;
    case cad::SurfaceKind::cylinder:
      return 1 / f.cylinder.Radius();
    case cad::SurfaceKind::sphere:
      return 1 / f.sphere.Radius();
    default:
      break;
  }
  try {
    const auto uv = cad::foot_parameters(m, cad::thread_state(m, serial_), patch.value - 1, p);
    if (!uv) return std::nullopt;
    GeomLProp_SLProps props(f.surface, (*uv)[0], (*uv)[1], 2, 1e-9);
    if (!props.IsCurvatureDefined()) return std::nullopt;
    return std::max(std::fabs(props.MaxCurvature()), std::fabs(props.MinCurvature()));
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
}

double CadOracle::distance_to_other_patches(const Point3& p, const std::vector<PatchId>& patches,
                                            double limit) const {
  const Model& m = *model_;
  // The other faces with a candidate box (a triangle's, inflated by its
  // deviation from the face) within the limit; then their exact closest points.
  std::vector<int> near;
  const double limit2 = limit * limit;
  m.candidate_tree.traverse([&](const Box3& box) { return squared_distance(box, p) < limit2; },
                            [&](int c) {
                              const int face = m.candidates[c].face;
                              const auto is = [face](const auto& x) { return x == face; };
                              const auto bounds = [face](PatchId q) { return q.value == face + 1; };
                              if (std::none_of(patches.begin(), patches.end(), bounds) &&
                                  std::none_of(near.begin(), near.end(), is)) {
                                near.push_back(face);
                              }
                              return true;
                            });
  // Newton only: where it does not converge the answer errs towards the limit.
  double best = limit;
  try {
    cad::ThreadState& ts = cad::thread_state(m, serial_);
    for (int face : near) best = cad::distance_to_face(m, ts, face, p, best);
  } catch (const Standard_Failure&) {
  }
  return best;
}

double CadOracle::exact_volume(SubdomainId id) const {
  double v = 0;
  for (const cad::SolidPiece& piece : model_->pieces) {
    if (id == kOutside || piece.id == id) v += piece.volume;
  }
  return v;
}

double CadOracle::exact_area(PatchId id) const {
  double a = 0;
  try {
    for (std::size_t i = 0; i < model_->faces.size(); ++i) {
      if (id.value != 0 && model_->patches[i].id != id) continue;
      GProp_GProps props;
      BRepGProp::SurfaceProperties(model_->faces[i].face, props);
      a += props.Mass();
    }
  } catch (const Standard_Failure& e) {
    rethrow_occt(e, "exact_area");
  }
  return a;
}

std::unique_ptr<CadOracle> load_cad_file(const std::string& path, const CadOptions& options) {
  cad::ReadShape read = cad::read_shape(path, options);
  // Three times the read's, in CPU seconds: valid parts prepare in seconds, a
  // malformed one once took hours.
  const auto deadline =
      cad::PrepDeadline::starting_now(3 * cad::read_time_limit_seconds(options, path));
  return std::make_unique<CadOracle>(cad::build_model(std::move(read), path, deadline));
}

}  // namespace rdmesh
