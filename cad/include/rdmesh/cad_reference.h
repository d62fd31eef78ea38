// OpenCASCADE's own answers on a CadOracle's model, to check the oracle against
// in tests and benchmarks. Slow, and independent of the oracle's tessellation
// and Newton solvers: crossings come from IntCurvesFace_Intersector on every
// face whose box the segment meets, distances from GeomAPI_ProjectPointOnSurf
// and BRepExtrema.
// Not thread-safe (one object per thread).
#pragma once

#include <memory>
#include <optional>

#include "rdmesh/cad_oracle.h"

namespace rdmesh {

class CadReference {
 public:
  explicit CadReference(const CadOracle& oracle);
  ~CadReference();
  CadReference(const CadReference&) = delete;
  CadReference& operator=(const CadReference&) = delete;

  /// The crossing of segment [a, b] with a face nearest to a (IN or ON the face;
  /// `tangent` for a tangent transition or ON), same conventions as
  /// CadOracle::first_crossing.
  std::optional<CadOracle::Crossing> first_crossing(const Point3& a, const Point3& b);

  /// The closest point of the (untrimmed) surface of `patch` to p.
  struct Foot {
    double distance = 0;   ///< from p; infinite when the projection fails
    bool in_face = false;  ///< its (u, v) classifies IN or ON the face
  };
  Foot foot(const Point3& p, PatchId patch);

  /// Distance from p to the trimmed face of `patch` (BRepExtrema_DistShapeShape);
  /// infinite when it fails.
  double distance_to_face(const Point3& p, PatchId patch);

  /// The oracle's (u, v) classification (its cells) against the face's
  /// BRepTopAdaptor_FClass2d, at `per_face` points of every face: half random
  /// in the face's (u, v) box, half near its pcurves (offset by 1e-5..1e-2 of
  /// the box). Points either side leaves undecided (the cells defer to the
  /// classifier, or the classifier answers ON) are not compared.
  /// `worst_undecided`: over the faces of positive (u, v) extent, the largest share of the random
  /// half that the cells leave to the classifier, whose slow path near the boundary takes
  /// milliseconds a point (check_cells only).
  struct CellCheck {
    int compared = 0;
    int disagree = 0;
    double worst_undecided = 0;
  };
  CellCheck check_cells(int per_face, unsigned seed);

  /// The cells' classification against the exact pcurves, at `per_face` points
  /// of every face offset from a pcurve by 1e-7..1e-2 of the face's (u, v) box:
  /// a point whose nearest boundary point lies inside a pcurve (not at a
  /// vertex, not on a seam) is in the face when it lies left of the boundary's
  /// direction there. Points the cells leave undecided are not compared.
  CellCheck check_cells_near_pcurves(int per_face, unsigned seed);

  /// The oracle's curves against their edges' 3D curves (GeomAPI_ProjectPointOnCurve),
  /// at `per_curve` parameters of every curve: the largest distance from
  /// point(t) to the exact curve beyond the end corrections that make point()
  /// meet the corners (the larger of the two at each end), and the number of
  /// curves whose evaluation goes through B-spline span caches.
  struct CurveCheck {
    double max_excess = 0;
    int cached_curves = 0;
    int curves = 0;
  };
  CurveCheck check_curves(int per_curve);

  /// The oracle's surface evaluation against Geom_Surface::D1 on a `per_side` x
  /// `per_side` grid over every face's (u, v) box, plus every interior knot line
  /// of a B-spline crossed at `per_side` points: the largest distance between
  /// the points, and the largest difference of the derivatives relative to their
  /// size (on the grid only: at a knot of lower continuity they are one-sided),
  /// and the number of faces whose evaluation goes through B-spline span caches.
  struct SurfaceCheck {
    double max_distance = 0;
    double max_derivative_error = 0;
    int cached_faces = 0;
    int faces = 0;
  };
  SurfaceCheck check_surfaces(int per_side);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rdmesh
