// Internal to cad/: the exact crossing of a segment with the faces, found from
// the tessellation's candidate triangles (face_tessellation.h). A triangle t
// stands for the surface over its (u, v) triangle, which lies within
// r = deviation (plus rounding) of it and has its normals in t's cone.
//
//  - Plane, cylinder, cone, sphere: the face's crossings are computed once per
//    query in closed form (analytic_roots.h).
//  - Any other surface: the segment can meet the surface over t only where it
//    is within r of t's plane and its shadow on that plane within r of t (the
//    window). When the segment is transversal to the whole cone
//    (|axis . d| > sin_cone) the surface over t is a graph it crosses at most
//    once there, so Newton on S(u, v) = a + w d, started where the segment
//    crosses t's plane, finds that crossing; a root inside t, or in the window
//    crossing the way the surface over t does, settles t. When the segment grazes the cone, or
//    Newton fails or ends elsewhere, t is cut into four, each measured again and treated the same
//    way, down to kMaxDepth levels; there OpenCASCADE's intersector
//    (occt_fallback.h) takes the face over that triangle's window (over the
//    whole segment after a few such windows, and for a face without
//    tessellation).
// Each crossing is classified in (u, v): inside cells are IN without the 2D
// classifier, outside cells are OUT, boundary cells ask the face's classifier
// (IN, or ON = on the boundary, which marks the hit tangent). The nearest
// crossing wins, except that among crossings within the tolerance of each other
// a transversal one beats one on a face boundary, which beats a grazing one.
#pragma once

#include <optional>

#include "cad_model.h"

namespace rdmesh::cad {

class ThreadState;
struct LineRoot;

/// The nearest crossing of segment a + w d, w in [0, length] (d a unit vector),
/// built up one candidate triangle at a time.
class RayQuery {
 public:
  RayQuery(const CadOracle::Model& m, ThreadState& ts, const Point3& a, const Point3& d,
           double length);
  /// Looks for crossings over candidate `c` of Model::candidates.
  void visit(int c);
  /// Crossings at or beyond this distance cannot improve the answer.
  double reach() const;
  const std::optional<RayHit>& best() const { return best_; }

 private:
  void closed_form(int face);
  void solve(const SurfaceTriangle& t, int depth);
  void subdivide(const SurfaceTriangle& t, int depth);
  /// Narrows [lo, hi] to where the segment can meet the surface over t: within
  /// r of t's plane, its shadow on the plane within r of t. False when empty.
  bool window(const SurfaceTriangle& t, double r, double& lo, double& hi) const;
  /// Whether Newton's root accounts for every crossing over transversal t.
  bool settles(const SurfaceTriangle& t, const LineRoot& root, double c, double lo,
               double hi) const;
  void consider_root(int face, const LineRoot& root);
  /// A crossing at distance w, (u, v) on face's surface with derivatives su, sv;
  /// `state` is its TopAbs_State in the face, or -1 when not classified yet.
  void consider(int face, double w, double u, double v, const Point3& point, const Point3& su,
                const Point3& sv, int state, bool tangent = false);
  /// OpenCASCADE's crossings of `face` for w in [w0, w1].
  void occt(int face, double w0, double w1);

  const CadOracle::Model& m_;
  ThreadState& ts_;
  Point3 a_, d_;
  double length_;
  double slack_;  // rounding allowance of the window tests
  int work_ = 0;  // subdivisions so far in this query
  std::optional<RayHit> best_;
  int best_rank_ = 0;  // grazing 0, on a face boundary 1, transversal 2
};

}  // namespace rdmesh::cad
