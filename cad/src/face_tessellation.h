// Internal to cad/: a face's tessellation, used only to find where to look.
//
// The face's (u, v) box is cut by a kd-tree into cells. Each cell is known to be
// inside the face, outside it (dropped) or crossed by its boundary (pcurves
// sampled and boxed with a margin): a point in an inside cell needs no 2D
// classifier. Cells are split where the surface turns (normal spread), where
// they are large, and along the boundary. Every kept cell gives two flat
// triangles with (u, v) at their nodes; each triangle carries a bound on how far
// the surface over it strays from it (twice the largest deviation sampled at its
// edge midpoints and centroid: the exact factor is 4/3 for a quadratic surface)
// and a cone holding the surface normals over it (the widest sampled angle times
// 1.5 plus 0.02 rad). Both are measured, not assumed, and both err on the large side.
#pragma once

#include <cstdint>
#include <vector>

#include "rdmesh/geometry.h"

namespace rdmesh::cad {

struct FacePatch;
class SurfaceEvaluator;

/// Where a point of a face's (u, v) box lies relative to the face.
enum class UvState : std::uint8_t { outside, inside, boundary };

/// A kd-tree over a face's (u, v) box whose leaves are inside, outside or boundary cells.
class UvCells {
 public:
  struct Node {
    double split = 0;       ///< inner node: the cut value along `axis`
    int child = -1;         ///< inner node: the low child (the high one is child + 1); leaf: -1
    std::uint8_t axis = 0;  ///< 0: u, 1: v
    UvState state = UvState::boundary;  ///< leaf only
  };
  /// State of (u, v); (u, v) is first brought into the box by whole periods
  /// (`u_period`, `v_period`, 0 when not periodic). Outside the box: outside.
  UvState state_at(double u, double v) const;
  /// (u, v) shifted by whole periods towards the box.
  void normalise(double& u, double& v) const;

  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  double u_period = 0, v_period = 0;
  std::vector<Node> nodes;  // nodes[0] is the root; empty: everything is boundary
};

/// A flat triangle standing for the surface S over a triangle of the (u, v) domain.
struct SurfaceTriangle {
  int face = 0;
  double uv[3][2] = {};
  Point3 p[3];           ///< S(uv[k])
  Point3 n[3];           ///< unit surface normals (du x dv) at the nodes; zero where degenerate
  Point3 axis;           ///< unit normal of the flat triangle (du x dv side)
  double sin_cone = 1;   ///< every normal over the triangle is within asin(sin_cone) of axis
  double deviation = 0;  ///< |S(u, v) - flat(u, v)| stays below this over the triangle
  bool inside = false;   ///< the triangle's cell is an inside cell
};

/// Builds `f.cells` and appends the face's triangles to `out`. `size` is the
/// model's diagonal (caps cell sizes).
void tessellate_face(FacePatch& f, int face, const SurfaceEvaluator& surface, double size,
                     std::vector<SurfaceTriangle>& out);

/// The box of t's nodes widened by r on every side.
Box3 triangle_box(const SurfaceTriangle& t, double r);

/// Measures a triangle whose nodes (uv, p, n) are set: deviation, axis, cone.
/// Evaluates the surface at the triangle's edge midpoints and centroid.
void measure_triangle(const SurfaceEvaluator& surface, SurfaceTriangle& t);

}  // namespace rdmesh::cad
