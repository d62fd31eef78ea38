// Internal to cad/: a face's tessellation, used only to find where to look.
//
// The face's (u, v) box is cut by a kd-tree into cells (uv_cells.h): inside the
// face, outside it (dropped) or crossed by its boundary. Cells are split at the
// surface's C2 breaks, where the surface turns (normal spread) or bends (chord
// sagitta), where they are large, and along the boundary. Every kept cell gives two flat
// triangles with (u, v) at their nodes; each triangle carries a bound on how far
// the surface over it strays from it (twice the largest deviation sampled at its
// edge midpoints and centroid: the exact factor is 4/3 for a quadratic surface)
// and a cone holding the surface normals over it (the widest sampled angle times
// 1.5 plus 0.005 rad). Both are measured, not assumed, and both err on the large side.
#pragma once

#include <cstddef>
#include <vector>

#include "rdmesh/geometry.h"
#include "uv_cells.h"

namespace rdmesh::cad {

struct FacePatch;
class SurfaceEvaluator;

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

/// When preparing a read model must end: a valid model's surfaces are followed
/// in a second or two, a malformed one's (edge tolerances so large that every
/// (u, v) is near the boundary, where OpenCASCADE's classifier takes
/// milliseconds a point) could take hours. The limit is CPU time of the
/// preparing thread (cpu_time.h), so a loaded machine does not turn a valid
/// part away. Default: never.
struct PrepDeadline {
  double seconds = 0;    ///< the limit, CPU seconds; 0: none
  double start_cpu = 0;  ///< thread_cpu_seconds() when preparing began
  /// Starts the clock of a `seconds` limit (0: none).
  static PrepDeadline starting_now(double seconds);
  /// Throws InputError("preparing the model did not finish within N s ...") once
  /// passed. Reads the clock on one call in 32 (a system call each).
  void check() const;

 private:
  mutable unsigned calls_ = 0;
};

/// Builds `f.cells` and appends the face's triangles to `out`. `size` is the
/// model's diagonal (caps cell sizes). At most `max_nodes` cells (kd-tree
/// nodes) may be made: a face needing more throws InputError, for a surface
/// that strays wildly from its edges (a corrupt control point) would otherwise
/// be cut into 2^24 cells per branch, for hours. The shared STEP/BREP files need
/// at most 5,887 cells for a face and 96,000 for a model.
void tessellate_face(FacePatch& f, int face, const SurfaceEvaluator& surface, double size,
                     std::vector<SurfaceTriangle>& out, std::size_t max_nodes,
                     const PrepDeadline& deadline);

/// The most cells tessellate_face() may make for one face, and for a model of
/// `faces` faces in all (faces x 1024 above a million).
constexpr std::size_t kMaxFaceCells = std::size_t{1} << 18;
constexpr std::size_t max_model_cells(std::size_t faces) {
  return (std::size_t{1} << 20) + 1024 * faces;
}

/// The box of t's nodes widened by r on every side.
Box3 triangle_box(const SurfaceTriangle& t, double r);

/// S and its unit normal at one (u, v); `regular` when the normal there is
/// defined (not a pole): then it depends on (u, v) alone and can be reused.
struct SurfaceSample {
  Point3 p, n;
  bool regular = false;
};

/// Measures a triangle whose nodes (uv, p, n) are set: deviation, axis, cone.
/// Evaluates the surface at the triangle's edge midpoints and centroid;
/// `midpoints`, when given, holds the samples at the midpoints of the edges
/// (k, k + 1) already taken (0.5 * (uv[k] + uv[k + 1]) exactly), and regular ones
/// are not evaluated again.
void measure_triangle(const SurfaceEvaluator& surface, SurfaceTriangle& t,
                      const SurfaceSample* midpoints = nullptr);

}  // namespace rdmesh::cad
