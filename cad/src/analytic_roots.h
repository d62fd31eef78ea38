// Internal to cad/: where a line meets a plane, cylinder, cone or sphere, in
// closed form (a linear or quadratic equation in the line parameter), with the
// surface parameters of each crossing as OpenCASCADE defines them.
#pragma once

#include "rdmesh/geometry.h"

namespace rdmesh::cad {

struct FacePatch;

struct AnalyticRoot {
  double w = 0;  ///< line parameter: the crossing is a + w d
  double u = 0, v = 0;
};

/// Crossings of the line a + w d (d a unit vector) with the whole analytic
/// surface of `f` (f.kind is not parametric), ascending in w. Returns how many
/// (0, 1 or 2); a tangent line gives its touching point once. A line lying in
/// the surface gives none.
int analytic_roots(const FacePatch& f, const Point3& a, const Point3& d, AnalyticRoot out[2]);

/// S(u, v) and its first derivatives on the analytic surface of `f`.
void analytic_d1(const FacePatch& f, double u, double v, Point3& p, Point3& su, Point3& sv);

}  // namespace rdmesh::cad
