// Internal to cad/: the OpenCASCADE data behind a CadOracle.
#pragma once

#include <BRepTopAdaptor_FClass2d.hxx>
#include <BSplCLib_Cache.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Cone.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>
#include <gp_Sphere.hxx>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "face_tessellation.h"
#include "occupancy_grid.h"
#include "rdmesh/box_tree.h"
#include "rdmesh/cad_oracle.h"
#include "rdmesh/errors.h"
#include "rdmesh/feature_table.h"

class StepData_StepModel;

namespace rdmesh::cad {

/// What a file says about a face: its name and colour ("#rrggbb"), each may be empty.
struct ShapeStyle {
  std::string name;
  std::string color;
};

/// A shape as read from a file, with the names the file gives its solids and
/// the names and colours it gives its faces.
struct ReadShape {
  TopoDS_Shape shape;
  std::vector<std::pair<TopoDS_Shape, std::string>> solid_names;
  std::vector<std::pair<TopoDS_Shape, ShapeStyle>> face_styles;
  std::vector<std::string> log;
};

/// Rejects a BREP text file whose section headers announce more entries than
/// the file holds (truncated; BRepTools would read on for billions of entries)
/// (shape_checks.cpp). Throws InputError.
void check_brep_text(const std::string& path);
/// Rejects a STEP model with a non-finite point, direction or vector, on
/// which the transfer would loop forever (shape_checks.cpp). Throws InputError.
void check_step_numbers(const Handle(StepData_StepModel) & model, const std::string& path);
/// Rejects a shape with a non-finite vertex or bounding box or a face on a
/// degenerate analytic surface (a radius not positive) (shape_checks.cpp).
/// Throws InputError.
void check_shape_geometry(const TopoDS_Shape& shape, const std::string& path);

/// Reads `path` by extension (cad_read.cpp), in a child process when options.isolate
/// (isolated_read.h). Throws InputError.
ReadShape read_shape(const std::string& path, const CadOptions& options);

/// One edge as an rdmesh Curve (cad_curve.cpp): the edge's 3D curve on
/// [t0, t1] plus a linear blend of the end corrections q0 - c(t0), q1 - c(t1),
/// so that point(t0) == q0 and point(t1) == q1 exactly.
class EdgeCurve final : public Curve {
 public:
  EdgeCurve(Handle(Geom_Curve) curve, double t0, double t1, Point3 q0, Point3 q1, int samples);
  Point3 point(double t) const override;
  double length(double ta, double tb) const override;
  double parameter_at_length(double ta, double s) const override;
  double closest(const Point3& p, double ta, double tb) const override;
  std::vector<double> plane_crossings(const Point3& normal, double offset, double ta,
                                      double tb) const override;
  /// OpenCASCADE's curvature of the edge's 3D curve (GeomLProp_CLProps); 0
  /// where its tangent is undefined.
  double curvature(double t) const override;
  /// The edge's 3D curve (before the end corrections), for reference checks.
  const Handle(Geom_Curve) & geometry() const { return curve_; }
  /// Whether point() reads B-spline span caches rather than the Geom_Curve.
  bool cached() const { return !spans_.empty(); }

 private:
  Point3 derivative(double t) const;
  /// The curve's own C(t), C'(t) and (when d2) C''(t): from the span's cache for
  /// a B-spline, else from the Geom_Curve.
  void evaluate(double t, gp_Pnt& p, gp_Vec* d1, gp_Vec* d2) const;
  /// Fills spans_ when `basis` (curve_ without its trimming) is a non-periodic B-spline.
  void build_span_caches(const Handle(Geom_Curve) & basis);
  double speed_integral(double u, double v) const;  // Gauss-Legendre on one cell
  double arc(double t) const;                       // length from t0 to t
  int samples_over(double ta, double tb) const;
  Handle(Geom_Curve) curve_;
  /// B-spline curves: one polynomial cache per knot span meeting [t0, t1]
  /// (span k starts at span_start_[k]), built once. Evaluating a cache is
  /// const, so queries stay thread-safe; de Boor's algorithm on every call
  /// (Geom_BSplineCurve::D0) was the planner's main cost on drill.
  std::vector<Handle(BSplCLib_Cache)> spans_;
  std::vector<double> span_start_;
  double spans_end_ = 0;
  /// A Geom_Line: point(t) is affine in t (the end corrections blend linearly
  /// too), so closest() and plane_crossings() are solved in closed form.
  bool straight_ = false;
  /// A Geom_Circle (null otherwise): closest() takes the angle of p around its
  /// axis (the end corrections, within the tolerance, move the answer by a
  /// second-order amount).
  Handle(Geom_Circle) circle_;
  double t0_, t1_;
  Point3 d0_, d1_;
  int samples_;
  double cell_;
  std::vector<double> cumulative_;  // arc(t0 + k * cell_)
  double total_length_ = 0;         // length(t0, t1), computed once
};

struct SolidPiece {
  TopoDS_Solid solid;
  SubdomainId id;
  Box3 box;
  /// OpenCASCADE's exact volume (BRepGProp), found once when the model is
  /// built: sizes and the fidelity check ask for it again, and on B-spline
  /// solids it takes a good part of a second.
  double volume = 0;
};

/// How a face's crossings with a line are computed (face_intersector.cpp).
enum class SurfaceKind {
  plane,       ///< in closed form (one root)
  cylinder,    ///< in closed form (a quadratic in the line parameter)
  cone,        ///< in closed form (a quadratic)
  sphere,      ///< in closed form (a quadratic)
  parametric,  ///< any other surface: Newton from the tessellation's triangles
};

/// One edge of a face as a 3D curve with a coarse polyline, for project().
struct BoundaryCurve {
  Handle(Geom_Curve) curve;  // with the edge's location applied
  std::vector<double> t;     // increasing parameters of the polyline's points
  std::vector<Point3> points;
};

struct FacePatch {
  TopoDS_Face face;
  Handle(Geom_Surface) surface;  // with the face's location applied
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  Box3 box;
  /// Used while building the model (seeds, cells); queries use per-thread copies.
  std::unique_ptr<BRepTopAdaptor_FClass2d> classifier;
  SurfaceKind kind = SurfaceKind::parametric;
  gp_Pln plane;  // the analytic surface matching `kind`
  gp_Cylinder cylinder;
  gp_Cone cone;
  gp_Sphere sphere;
  /// Where the face lies in its (u, v) box: inside cells skip the classifier.
  UvCells cells;
  /// This face's triangles are Model::triangles[first_triangle, end_triangle).
  int first_triangle = 0, end_triangle = 0;
  /// Over this face's triangles (indices relative to first_triangle), for project().
  BoxTree triangle_tree;
  std::vector<BoundaryCurve> boundary;
  /// The face's normal (surface normal, flipped for a reversed face) points out
  /// of subdomain `outward_of` into subdomain `inward_of` (either may be 0).
  SubdomainId outward_of, inward_of;
};

/// An item of the candidate tree: a triangle of a parametric face, or a whole
/// face (triangle -1) answered in closed form or, without a tessellation, by
/// OpenCASCADE.
struct Candidate {
  int face = 0;
  int triangle = -1;  ///< index into Model::triangles
};

/// The nearest crossing of a ray with a face.
struct RayHit {
  double distance = 0;  ///< along the ray
  int face = 0;         ///< index of the patch's face
  Point3 point;
  double cosine = 0;     ///< between the face's outward normal and the ray
  bool tangent = false;  ///< grazing, or on the face's boundary
};

}  // namespace rdmesh::cad

namespace rdmesh {

struct CadOracle::Model {
  TopoDS_Shape shape;  // the conformal compound of the solid pieces
  int input_solids = 0;
  std::vector<cad::SolidPiece> pieces;
  std::vector<SubdomainInfo> subdomains;
  std::vector<cad::FacePatch> faces;  // index = patch id - 1
  /// Every face's tessellation (FacePatch::first_triangle..).
  std::vector<cad::SurfaceTriangle> triangles;
  /// What a segment is tested against, in one tree over their boxes: the
  /// triangles of every tessellated face (boxes inflated by their deviation;
  /// an analytic face is intersected in closed form once per query, whichever
  /// of its triangles is met first), and an untessellated face as a whole.
  std::vector<cad::Candidate> candidates;
  BoxTree candidate_tree;
  cad::OccupancyGrid occupied;  ///< the grid cells the candidates' boxes meet
  std::vector<PatchInfo> patches;
  /// The file's face names and colours, carried to the faces after the fuse.
  std::vector<std::pair<TopoDS_Shape, cad::ShapeStyle>> face_styles;
  std::vector<std::string> patch_colors;  // index = patch id - 1; "#rrggbb" or ""
  /// The edges' curves, the vertices ending them (corners), each face's seeds.
  FeatureTable<cad::EdgeCurve> features;
  Box3 box;
  double tolerance = 0;
  std::vector<std::string> log;
  /// What the user should know about the model (solids that got no volume).
  std::vector<std::string> warnings;
};

namespace cad {
/// Builds the oracle data from a read shape (cad_build.cpp). Throws InputError.
/// `deadline` bounds the time of the tessellation (face_tessellation.h).
std::unique_ptr<CadOracle::Model> build_model(ReadShape read, const std::string& source,
                                              const PrepDeadline& deadline = {});
/// Picks points inside each face from its tessellation, built first (cad_seeds.cpp).
void compute_seeds(CadOracle::Model& model);
/// Builds each face's cells, triangles and boundary curves, and the triangle trees
/// (face_tessellation.cpp, face_boundary.cpp).
void build_accelerator(CadOracle::Model& model, const PrepDeadline& deadline);
/// Removes OpenCASCADE's message printers (once; its translators print to stdout).
void silence_opencascade();
/// "STANDARD_FAILURE_TYPE: message" of an OpenCASCADE exception.
std::string describe(const Standard_Failure& e);
}  // namespace cad

}  // namespace rdmesh
