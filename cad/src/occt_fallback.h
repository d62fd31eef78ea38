// Internal to cad/: OpenCASCADE's own line/face intersectors, kept as the
// fallback of the Newton intersector (face_intersector.cpp) where it cannot
// decide: Newton fails near a candidate, or the line grazes the surface below
// the tessellation's finest subdivision, or the face has no tessellation.
//
// Torus, cylinder, cone and sphere: IntCurveSurface_HInter in closed form.
// B-spline and Bezier: IntCurveSurface_HInter against a sampled polyhedron built
// once (per thread). Any other surface: IntCurvesFace_Intersector. The object
// keeps state: one per face and thread.
#pragma once

#include <memory>
#include <vector>

#include "rdmesh/geometry.h"

class IntCurvesFace_Intersector;

namespace rdmesh::cad {

struct FacePatch;
struct SampledFace;

class OcctFaceIntersector {
 public:
  struct Hit {
    double w = 0, u = 0, v = 0;
    Point3 point;
    bool tangent = false;  ///< OpenCASCADE's transition says tangent
    int state = -1;        ///< -1: not classified yet; else TopAbs_IN or TopAbs_ON
  };
  OcctFaceIntersector(const FacePatch& f, double tolerance);
  ~OcctFaceIntersector();
  /// Crossings of the line a + w d (d a unit vector) with the face's surface
  /// for w in [w0, w1]. Throws Standard_Failure.
  void intersect(const Point3& a, const Point3& d, double w0, double w1, std::vector<Hit>& out);

 private:
  const FacePatch& face_;
  double tolerance_;
  std::unique_ptr<SampledFace> sampled_;
  std::unique_ptr<IntCurvesFace_Intersector> general_;
};

}  // namespace rdmesh::cad
