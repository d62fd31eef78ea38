// OpenCASCADE line/face intersection (occt_fallback.h).
#include "occt_fallback.h"

#include <Bnd_BoundSortBox.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_Line.hxx>
#include <IntCurveSurface_HInter.hxx>
#include <IntCurveSurface_IntersectionPoint.hxx>
#include <IntCurveSurface_ThePolygonOfHInter.hxx>
#include <IntCurveSurface_ThePolyhedronOfHInter.hxx>
#include <IntCurvesFace_Intersector.hxx>
#include <algorithm>
#include <gp_Lin.hxx>

#include "cad_model.h"

namespace rdmesh::cad {

// A sampled free-form face: its polyhedron seeds IntCurveSurface_HInter.
struct SampledFace {
  Handle(GeomAdaptor_Surface) surface;
  std::unique_ptr<IntCurveSurface_ThePolyhedronOfHInter> polyhedron;
  Bnd_BoundSortBox boxes;
};

namespace {

gp_Pnt to_gp(const Point3& p) { return {p.x, p.y, p.z}; }
Point3 to_point(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

}  // namespace

OcctFaceIntersector::OcctFaceIntersector(const FacePatch& f, double tolerance)
    : face_(f), tolerance_(tolerance) {}

OcctFaceIntersector::~OcctFaceIntersector() = default;

void OcctFaceIntersector::intersect(const Point3& a, const Point3& d, double w0, double w1,
                                    std::vector<Hit>& out) {
  if (!(w1 > w0)) return;
  const FacePatch& f = face_;
  const GeomAdaptor_Surface probe(f.surface);
  const GeomAbs_SurfaceType type = probe.GetType();
  const bool closed_form = type == GeomAbs_Cylinder || type == GeomAbs_Cone ||
                           type == GeomAbs_Sphere || type == GeomAbs_Torus;
  const bool spline = type == GeomAbs_BSplineSurface || type == GeomAbs_BezierSurface;
  if (closed_form || spline) {
    const Handle(Geom_Line) line = new Geom_Line(to_gp(a), gp_Dir(d.x, d.y, d.z));
    const Handle(GeomAdaptor_Curve) curve = new GeomAdaptor_Curve(line, w0, w1);
    IntCurveSurface_HInter inter;
    if (closed_form) {
      inter.Perform(curve, new GeomAdaptor_Surface(f.surface, f.u0, f.u1, f.v0, f.v1));
    } else {
      if (!sampled_) {  // sample the face once, then reuse the polyhedron
        sampled_ = std::make_unique<SampledFace>();
        sampled_->surface = new GeomAdaptor_Surface(f.surface, f.u0, f.u1, f.v0, f.v1);
        const Handle(GeomAdaptor_Surface)& s = sampled_->surface;
        const int nu = std::clamp(s->NbUIntervals(GeomAbs_C2) * (s->UDegree() + 1), 10, 50);
        const int nv = std::clamp(s->NbVIntervals(GeomAbs_C2) * (s->VDegree() + 1), 10, 50);
        sampled_->polyhedron = std::make_unique<IntCurveSurface_ThePolyhedronOfHInter>(
            s, nu, nv, f.u0, f.v0, f.u1, f.v1);
        sampled_->polyhedron->FillBounding();
        sampled_->boxes.Initialize(sampled_->polyhedron->Bounding(),
                                   sampled_->polyhedron->ComponentsBounding());
      }
      const IntCurveSurface_ThePolygonOfHInter polygon(curve, w0, w1, 3);
      inter.Perform(curve, polygon, sampled_->surface, *sampled_->polyhedron, sampled_->boxes);
    }
    if (!inter.IsDone()) return;
    for (int k = 1; k <= inter.NbPoints(); ++k) {
      const IntCurveSurface_IntersectionPoint& ip = inter.Point(k);
      Hit h;
      h.w = ip.W(), h.u = ip.U(), h.v = ip.V();
      h.point = to_point(ip.Pnt());
      h.tangent = ip.Transition() == IntCurveSurface_Tangent;
      out.push_back(h);
    }
    return;
  }
  if (!general_) general_ = std::make_unique<IntCurvesFace_Intersector>(f.face, 0.1 * tolerance_);
  general_->Perform(gp_Lin(to_gp(a), gp_Dir(d.x, d.y, d.z)), w0, w1);
  if (!general_->IsDone()) return;
  for (int k = 1; k <= general_->NbPnt(); ++k) {
    Hit h;
    h.w = general_->WParameter(k), h.u = general_->UParameter(k), h.v = general_->VParameter(k);
    h.point = to_point(general_->Pnt(k));
    h.tangent = general_->Transition(k) == IntCurveSurface_Tangent;
    h.state = general_->State(k);
    out.push_back(h);
  }
}

}  // namespace rdmesh::cad
