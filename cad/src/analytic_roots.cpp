// Closed-form line/surface crossings (analytic_roots.h).
#include "analytic_roots.h"

#include <ElSLib.hxx>
#include <algorithm>
#include <cmath>

#include "cad_model.h"

namespace rdmesh::cad {
namespace {

gp_Pnt to_gp(const Point3& p) { return {p.x, p.y, p.z}; }
Point3 to_point(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

// Coordinates of a and d in the frame `ax` (origin, X, Y, Z).
struct Local {
  Point3 a, d;
};
Local local(const gp_Ax3& ax, const Point3& a, const Point3& d) {
  const Point3 o = to_point(ax.Location().XYZ()), x = to_point(ax.XDirection().XYZ()),
               y = to_point(ax.YDirection().XYZ()), z = to_point(ax.Direction().XYZ());
  const Point3 r = a - o;
  return {{dot(r, x), dot(r, y), dot(r, z)}, {dot(d, x), dot(d, y), dot(d, z)}};
}

// Real roots of A w^2 + 2 B w + C = 0, ascending (stable form; a double root once).
int quadratic(double A, double B, double C, double w[2]) {
  const double scale = std::max({std::fabs(A), std::fabs(B), std::fabs(C)});
  if (!(scale > 0)) return 0;
  if (std::fabs(A) <= 1e-15 * scale) {  // linear
    if (B == 0) return 0;
    w[0] = -C / (2 * B);
    return 1;
  }
  const double disc = B * B - A * C;
  if (disc < 0) return 0;
  if (disc == 0) {
    w[0] = -B / A;
    return 1;
  }
  const double q = -(B + std::copysign(std::sqrt(disc), B));
  w[0] = q / A;
  w[1] = C / q;
  if (w[0] > w[1]) std::swap(w[0], w[1]);
  return 2;
}

double angle_0_2pi(double y, double x) {
  const double t = std::atan2(y, x);
  return t < 0 ? t + 2 * M_PI : t;
}

}  // namespace

int analytic_roots(const FacePatch& f, const Point3& a, const Point3& d, AnalyticRoot out[2]) {
  double w[2];
  int n = 0;
  switch (f.kind) {
    case SurfaceKind::plane: {
      const Local l = local(f.plane.Position(), a, d);
      if (l.d.z == 0) return 0;
      w[0] = -l.a.z / l.d.z;
      n = 1;
      break;
    }
    case SurfaceKind::cylinder: {
      const Local l = local(f.cylinder.Position(), a, d);
      const double r = f.cylinder.Radius();
      n = quadratic(l.d.x * l.d.x + l.d.y * l.d.y, l.a.x * l.d.x + l.a.y * l.d.y,
                    l.a.x * l.a.x + l.a.y * l.a.y - r * r, w);
      break;
    }
    case SurfaceKind::cone: {
      const Local l = local(f.cone.Position(), a, d);
      const double k = std::tan(f.cone.SemiAngle()), r0 = f.cone.RefRadius();
      const double rz = r0 + k * l.a.z;  // signed radius at a
      n = quadratic(l.d.x * l.d.x + l.d.y * l.d.y - k * k * l.d.z * l.d.z,
                    l.a.x * l.d.x + l.a.y * l.d.y - k * l.d.z * rz,
                    l.a.x * l.a.x + l.a.y * l.a.y - rz * rz, w);
      for (int i = 0; i < n; ++i) {  // P(u, v) = O + (r0 + v sin b)(cos u X + sin u Y) + v cos b Z
        const Point3 x = l.a + w[i] * l.d;
        const double v = x.z / std::cos(f.cone.SemiAngle());
        const double rho = r0 + v * std::sin(f.cone.SemiAngle());
        out[i].w = w[i];
        out[i].v = v;
        out[i].u = rho >= 0 ? angle_0_2pi(x.y, x.x) : angle_0_2pi(-x.y, -x.x);
      }
      return n;
    }
    case SurfaceKind::sphere: {
      const Point3 o = to_point(f.sphere.Location().XYZ());
      const Point3 r = a - o;
      const double radius = f.sphere.Radius();
      n = quadratic(1.0, dot(r, d), squared_norm(r) - radius * radius, w);
      break;
    }
    case SurfaceKind::parametric:
      return 0;
  }
  for (int i = 0; i < n; ++i) {
    const gp_Pnt x = to_gp(a + w[i] * d);
    out[i].w = w[i];
    switch (f.kind) {
      case SurfaceKind::plane:
        ElSLib::Parameters(f.plane, x, out[i].u, out[i].v);
        break;
      case SurfaceKind::cylinder:
        ElSLib::Parameters(f.cylinder, x, out[i].u, out[i].v);
        break;
      default:
        ElSLib::Parameters(f.sphere, x, out[i].u, out[i].v);
        break;
    }
  }
  return n;
}

void analytic_d1(const FacePatch& f, double u, double v, Point3& p, Point3& su, Point3& sv) {
  gp_Pnt q;
  gp_Vec du, dv;
  switch (f.kind) {
    case SurfaceKind::plane:
      ElSLib::D1(u, v, f.plane, q, du, dv);
      break;
    case SurfaceKind::cylinder:
      ElSLib::D1(u, v, f.cylinder, q, du, dv);
      break;
    case SurfaceKind::cone:
      ElSLib::D1(u, v, f.cone, q, du, dv);
      break;
    case SurfaceKind::sphere:
      ElSLib::D1(u, v, f.sphere, q, du, dv);
      break;
    case SurfaceKind::parametric:
      throw InternalError("analytic_d1 on a parametric face");
  }
  p = to_point(q.XYZ()), su = to_point(du.XYZ()), sv = to_point(dv.XYZ());
}

}  // namespace rdmesh::cad
