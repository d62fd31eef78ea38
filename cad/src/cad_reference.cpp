// OpenCASCADE reference answers (rdmesh/cad_reference.h).
#include "rdmesh/cad_reference.h"

#include <BRepAdaptor_Curve2d.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dAPI_ProjectPointOnCurve.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <IntCurvesFace_Intersector.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <gp_Lin.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec2d.hxx>
#include <limits>
#include <random>

#include "cad_model.h"
#include "surface_evaluator.h"

namespace rdmesh {

struct CadReference::Impl {
  const CadOracle::Model* model;
  std::vector<std::unique_ptr<IntCurvesFace_Intersector>> intersectors;
  std::vector<std::unique_ptr<BRepTopAdaptor_FClass2d>> classifiers;
};

namespace {

// Whether segment [a, b] meets the box.
bool meets(const Point3& a, const Point3& b, const Box3& box) {
  double t0 = 0, t1 = 1;
  return clip_line(a, b - a, box, t0, t1);
}

}  // namespace

CadReference::CadReference(const CadOracle& oracle) : impl_(std::make_unique<Impl>()) {
  impl_->model = &oracle.model();
  impl_->intersectors.resize(impl_->model->faces.size());
  impl_->classifiers.resize(impl_->model->faces.size());
}

CadReference::~CadReference() = default;

std::optional<CadOracle::Crossing> CadReference::first_crossing(const Point3& a, const Point3& b) {
  const CadOracle::Model& m = *impl_->model;
  const Point3 d = b - a;
  const double len = norm(d);
  if (!(len > 0)) return std::nullopt;
  const gp_Lin line(gp_Pnt(a.x, a.y, a.z), gp_Dir(d.x, d.y, d.z));
  std::optional<CadOracle::Crossing> best;
  try {
    for (std::size_t i = 0; i < m.faces.size(); ++i) {
      const cad::FacePatch& f = m.faces[i];
      if (!meets(a, b, f.box)) continue;
      std::unique_ptr<IntCurvesFace_Intersector>& x = impl_->intersectors[i];
      if (!x) x = std::make_unique<IntCurvesFace_Intersector>(f.face, 0.1 * m.tolerance);
      try {
        x->Perform(line, 0.0, len);
      } catch (const Standard_Failure&) {
        continue;
      }
      if (!x->IsDone()) continue;
      for (int k = 1; k <= x->NbPnt(); ++k) {
        const double w = x->WParameter(k);
        if (w < 0 || w > len || (best && w >= best->distance)) continue;
        gp_Pnt p;
        gp_Vec du, dv;
        f.surface->D1(x->UParameter(k), x->VParameter(k), p, du, dv);
        gp_Vec n = du.Crossed(dv);
        if (f.face.Orientation() == TopAbs_REVERSED) n.Reverse();
        const double nn = n.Magnitude();
        CadOracle::Crossing c;
        c.point = {x->Pnt(k).X(), x->Pnt(k).Y(), x->Pnt(k).Z()};
        c.patch = m.patches[i].id;
        c.distance = w;
        c.cosine = nn > 0 ? (n.X() * d.x + n.Y() * d.y + n.Z() * d.z) / (nn * len) : 0.0;
        c.tangent = x->Transition(k) == IntCurveSurface_Tangent || x->State(k) == TopAbs_ON;
        best = c;
      }
    }
  } catch (const Standard_Failure& e) {
    throw OracleError("OpenCASCADE failed in CadReference::first_crossing: " + cad::describe(e));
  }
  return best;
}

CadReference::Foot CadReference::foot(const Point3& p, PatchId patch) {
  const CadOracle::Model& m = *impl_->model;
  Foot out;
  out.distance = std::numeric_limits<double>::infinity();
  if (patch.value < 1 || patch.value > static_cast<int>(m.faces.size())) return out;
  const cad::FacePatch& f = m.faces[patch.value - 1];
  try {
    GeomAPI_ProjectPointOnSurf proj(gp_Pnt(p.x, p.y, p.z), f.surface, f.u0, f.u1, f.v0, f.v1);
    if (proj.NbPoints() == 0) return out;
    double u, v;
    proj.LowerDistanceParameters(u, v);
    out.distance = proj.LowerDistance();
    std::unique_ptr<BRepTopAdaptor_FClass2d>& c = impl_->classifiers[patch.value - 1];
    if (!c) c = std::make_unique<BRepTopAdaptor_FClass2d>(f.face, BRep_Tool::Tolerance(f.face));
    const TopAbs_State s = c->Perform(gp_Pnt2d(u, v));
    out.in_face = s == TopAbs_IN || s == TopAbs_ON;
  } catch (const Standard_Failure& e) {
    throw OracleError("OpenCASCADE failed in CadReference::foot: " + cad::describe(e));
  }
  return out;
}

double CadReference::distance_to_face(const Point3& p, PatchId patch) {
  const CadOracle::Model& m = *impl_->model;
  if (patch.value < 1 || patch.value > static_cast<int>(m.faces.size())) {
    return std::numeric_limits<double>::infinity();
  }
  try {
    BRepExtrema_DistShapeShape dist(BRepBuilderAPI_MakeVertex(gp_Pnt(p.x, p.y, p.z)).Vertex(),
                                    m.faces[patch.value - 1].face);
    if (!dist.IsDone() || dist.NbSolution() == 0) return std::numeric_limits<double>::infinity();
    return dist.Value();
  } catch (const Standard_Failure& e) {
    throw OracleError("OpenCASCADE failed in CadReference::distance_to_face: " + cad::describe(e));
  }
}

CadReference::CellCheck CadReference::check_cells(int per_face, unsigned seed) {
  const CadOracle::Model& m = *impl_->model;
  CellCheck out;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  try {
    for (std::size_t i = 0; i < m.faces.size(); ++i) {
      const cad::FacePatch& f = m.faces[i];
      std::unique_ptr<BRepTopAdaptor_FClass2d>& c = impl_->classifiers[i];
      if (!c) c = std::make_unique<BRepTopAdaptor_FClass2d>(f.face, BRep_Tool::Tolerance(f.face));
      std::vector<BRepAdaptor_Curve2d> pcurves;
      for (TopExp_Explorer ex(f.face, TopAbs_EDGE); ex.More(); ex.Next()) {
        pcurves.emplace_back(TopoDS::Edge(ex.Current()), f.face);
      }
      const double du = f.u1 - f.u0, dv = f.v1 - f.v0;
      int random = 0, undecided = 0;
      for (int k = 0; k < per_face; ++k) {
        double u = f.u0 + uniform(rng) * du, v = f.v0 + uniform(rng) * dv;
        if (k % 2 && !pcurves.empty()) {  // near the boundary
          const BRepAdaptor_Curve2d& pc = pcurves[static_cast<std::size_t>(k / 2) % pcurves.size()];
          const gp_Pnt2d q = pc.Value(pc.FirstParameter() +
                                      uniform(rng) * (pc.LastParameter() - pc.FirstParameter()));
          const double r = std::pow(10.0, -5 + 3 * uniform(rng)), angle = 2 * M_PI * uniform(rng);
          u = q.X() + r * du * std::cos(angle), v = q.Y() + r * dv * std::sin(angle);
        }
        const cad::UvState mine = f.cells.state_at(u, v);
        if (k % 2 == 0) {
          ++random;
          undecided += mine == cad::UvState::boundary;
        }
        if (mine == cad::UvState::boundary) continue;
        const TopAbs_State theirs = c->Perform(gp_Pnt2d(u, v));
        if (theirs != TopAbs_IN && theirs != TopAbs_OUT) continue;
        ++out.compared;
        out.disagree += (mine == cad::UvState::inside) != (theirs == TopAbs_IN);
      }
      if (random > 0 && std::min(du, dv) > 1e-6 * std::max(du, dv)) {  // not flat in (u, v)
        out.worst_undecided =
            std::max(out.worst_undecided, static_cast<double>(undecided) / random);
      }
    }
  } catch (const Standard_Failure& e) {
    throw OracleError("OpenCASCADE failed in CadReference::check_cells: " + cad::describe(e));
  }
  return out;
}

CadReference::CellCheck CadReference::check_cells_near_pcurves(int per_face, unsigned seed) {
  const CadOracle::Model& m = *impl_->model;
  CellCheck out;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  struct Pcurve {
    Handle(Geom2d_Curve) curve;
    double t0, t1;
    double sense;  // +1 when the face's boundary runs along increasing t
    bool seam;
  };
  try {
    for (const cad::FacePatch& f : m.faces) {
      // Edge orientations as seen from the face taken FORWARD: the face lies
      // left of its boundary's direction in (u, v).
      const TopoDS_Face face = TopoDS::Face(f.face.Oriented(TopAbs_FORWARD));
      std::vector<Pcurve> pcurves;
      for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
        const TopoDS_Edge& e = TopoDS::Edge(ex.Current());
        if (BRep_Tool::Degenerated(e)) continue;
        Pcurve pc;
        pc.curve = BRep_Tool::CurveOnSurface(e, face, pc.t0, pc.t1);
        if (pc.curve.IsNull() || !(pc.t1 > pc.t0)) continue;
        pc.sense = e.Orientation() == TopAbs_REVERSED ? -1 : 1;
        pc.seam = BRep_Tool::IsClosed(e, face);
        pcurves.push_back(pc);
      }
      if (pcurves.empty()) continue;
      const double size = std::hypot(f.u1 - f.u0, f.v1 - f.v0);
      for (int k = 0; k < per_face; ++k) {
        const Pcurve& pc = pcurves[static_cast<std::size_t>(k) % pcurves.size()];
        gp_Pnt2d q;
        gp_Vec2d t;
        pc.curve->D1(pc.t0 + (0.05 + 0.9 * uniform(rng)) * (pc.t1 - pc.t0), q, t);
        if (!(t.Magnitude() > 0)) continue;
        const double offset = std::pow(10.0, -7 + 5 * uniform(rng)) * size;
        const double side = uniform(rng) < 0.5 ? -1 : 1;
        const gp_Vec2d n = gp_Vec2d(-t.Y(), t.X()).Normalized();
        const gp_Pnt2d p(q.X() + side * offset * n.X(), q.Y() + side * offset * n.Y());
        // The nearest boundary point over every pcurve.
        double best = std::numeric_limits<double>::infinity(), best_t = 0;
        const Pcurve* nearest = nullptr;
        for (const Pcurve& c : pcurves) {
          Geom2dAPI_ProjectPointOnCurve proj(p, c.curve, c.t0, c.t1);
          for (int i = 1; i <= proj.NbPoints(); ++i) {
            if (proj.Distance(i) < best)
              best = proj.Distance(i), best_t = proj.Parameter(i), nearest = &c;
          }
          for (double end : {c.t0, c.t1}) {  // a vertex nearer than any interior foot
            if (c.curve->Value(end).Distance(p) < best)
              best = c.curve->Value(end).Distance(p), nearest = nullptr;
          }
        }
        if (!nearest || nearest->seam) continue;
        const double span = nearest->t1 - nearest->t0;
        if (best_t - nearest->t0 < 1e-6 * span || nearest->t1 - best_t < 1e-6 * span) continue;
        const cad::UvState mine = f.cells.state_at(p.X(), p.Y());
        if (mine == cad::UvState::boundary) continue;
        gp_Pnt2d foot;
        gp_Vec2d dir;
        nearest->curve->D1(best_t, foot, dir);
        const double left =
            nearest->sense * (dir.X() * (p.Y() - foot.Y()) - dir.Y() * (p.X() - foot.X()));
        ++out.compared;
        out.disagree += (mine == cad::UvState::inside) != (left > 0);
      }
    }
  } catch (const Standard_Failure& e) {
    throw OracleError("OpenCASCADE failed in CadReference::check_cells_near_pcurves: " +
                      cad::describe(e));
  }
  return out;
}

CadReference::CurveCheck CadReference::check_curves(int per_curve) {
  const CadOracle::Model& m = *impl_->model;
  CurveCheck out;
  for (const CurveInfo& info : m.features.curves()) {
    const cad::EdgeCurve& c = m.features.curve(info.id);
    ++out.curves;
    if (c.cached()) ++out.cached_curves;
    const double t0 = info.t_begin, t1 = info.t_end;
    auto gap = [&](double t) {
      const gp_Pnt exact = c.geometry()->Value(t);
      return distance(c.point(t), Point3{exact.X(), exact.Y(), exact.Z()});
    };
    const double ends = std::max(gap(t0), gap(t1));  // the corrections, blended linearly
    for (int k = 0; k < per_curve; ++k) {
      const double t = t0 + (t1 - t0) * (k + 0.5) / per_curve;
      const Point3 p = c.point(t);
      GeomAPI_ProjectPointOnCurve projection(gp_Pnt(p.x, p.y, p.z), c.geometry(), t0, t1);
      if (projection.NbPoints() == 0) {
        out.max_excess = std::numeric_limits<double>::infinity();
        continue;
      }
      out.max_excess = std::max(out.max_excess, projection.LowerDistance() - ends);
    }
  }
  return out;
}

CadReference::SurfaceCheck CadReference::check_surfaces(int per_side) {
  const CadOracle::Model& m = *impl_->model;
  SurfaceCheck out;
  try {
    for (const cad::FacePatch& f : m.faces) {
      const cad::SurfaceEvaluator s(f);
      ++out.faces;
      if (s.cached()) ++out.cached_faces;
      auto compare = [&](double u, double v, bool derivatives) {
        Point3 p, su, sv;
        s.d1(u, v, p, su, sv);
        gp_Pnt q;
        gp_Vec qu, qv;
        f.surface->D1(u, v, q, qu, qv);
        out.max_distance = std::max(out.max_distance, distance(p, {q.X(), q.Y(), q.Z()}));
        if (!derivatives) return;
        const Point3 eu{qu.X(), qu.Y(), qu.Z()}, ev{qv.X(), qv.Y(), qv.Z()};
        const double scale = std::max({norm(eu), norm(ev), 1e-300});
        out.max_derivative_error = std::max(out.max_derivative_error,
                                            std::max(distance(su, eu), distance(sv, ev)) / scale);
      };
      auto at = [&](double lo, double hi, int k) { return lo + (hi - lo) * (k + 0.5) / per_side; };
      for (int i = 0; i < per_side; ++i) {
        for (int j = 0; j < per_side; ++j) compare(at(f.u0, f.u1, i), at(f.v0, f.v1, j), true);
      }
      for (double u : s.interior_knots(true)) {
        for (int j = 0; j < per_side; ++j) compare(u, at(f.v0, f.v1, j), false);
      }
      for (double v : s.interior_knots(false)) {
        for (int i = 0; i < per_side; ++i) compare(at(f.u0, f.u1, i), v, false);
      }
    }
  } catch (const Standard_Failure& e) {
    throw OracleError("OpenCASCADE failed in CadReference::check_surfaces: " + cad::describe(e));
  }
  return out;
}

}  // namespace rdmesh
