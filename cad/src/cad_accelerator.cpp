// The query accelerator of a model (cad_model.h: build_accelerator): every
// face's cells and triangles, the candidate tree (parametric faces' triangles
// with boxes inflated by their deviation, other faces whole) for
// intersections, one tree per face over its own triangles for projections, and
// each face's boundary curves.
#include <BRep_Tool.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <algorithm>
#include <string>

#include "cad_model.h"
#include "rdmesh/errors.h"
#include "surface_evaluator.h"

namespace rdmesh::cad {
namespace {

int curve_points(const Handle(Geom_Curve) & c, double t0, double t1) {
  const GeomAdaptor_Curve a(c, t0, t1);
  switch (a.GetType()) {
    case GeomAbs_Line:
      return 2;
    case GeomAbs_BSplineCurve:
    case GeomAbs_BezierCurve:
      return std::clamp(4 * a.NbIntervals(GeomAbs_C2) * std::max(a.Degree(), 2), 32, 512);
    default:
      return 32;
  }
}

std::vector<BoundaryCurve> boundary_curves(const TopoDS_Face& face) {
  std::vector<BoundaryCurve> out;
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(face, TopAbs_EDGE, edges);
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edges(i));
    if (BRep_Tool::Degenerated(e)) continue;
    double t0 = 0, t1 = 0;
    BoundaryCurve b;
    b.curve = BRep_Tool::Curve(e, t0, t1);
    if (b.curve.IsNull() || !(t1 > t0)) continue;
    const int n = curve_points(b.curve, t0, t1);
    for (int k = 0; k < n; ++k) {
      const double t = t0 + (t1 - t0) * k / (n - 1);
      const gp_Pnt p = b.curve->Value(t);
      b.t.push_back(t);
      b.points.push_back({p.X(), p.Y(), p.Z()});
    }
    out.push_back(std::move(b));
  }
  return out;
}

}  // namespace

void build_accelerator(CadOracle::Model& m, const PrepDeadline& deadline) {
  const double size = m.box.diagonal();
  std::vector<Box3> boxes;
  int untessellated = 0;
  // Room for a typical tessellation up front: growing a vector of a few MB by
  // doubling copies it and faults in fresh pages at each step. Pages reserved
  // but never written cost nothing.
  m.triangles.reserve(256 * m.faces.size());
  const std::size_t model_cells = max_model_cells(m.faces.size());
  std::size_t cells = 0;
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    FacePatch& f = m.faces[i];
    const int face = static_cast<int>(i);
    f.first_triangle = static_cast<int>(m.triangles.size());
    try {
      const SurfaceEvaluator s(f);
      const std::size_t left = model_cells - cells;
      try {
        tessellate_face(f, face, s, size, m.triangles, std::min(kMaxFaceCells, left), deadline);
      } catch (const InputError&) {
        if (left >= kMaxFaceCells) throw;
        throw InputError("following the model's " + std::to_string(m.faces.size()) +
                         " surfaces needs more than " + std::to_string(model_cells) +
                         " cells (surfaces far from their edges, as with corrupt control points?)");
      }
      cells += f.cells.nodes.size();
    } catch (const Standard_Failure&) {
      m.triangles.resize(f.first_triangle);
      f.cells = {};  // every (u, v) is a boundary one: the classifier decides
    }
    f.end_triangle = static_cast<int>(m.triangles.size());
    std::vector<Box3> own;
    for (int t = f.first_triangle; t < f.end_triangle; ++t) {
      own.push_back(triangle_box(m.triangles[t], 0));
    }
    f.triangle_tree = BoxTree(own);
    if (f.first_triangle == f.end_triangle) ++untessellated;
    // Triangle boxes for every tessellated face, analytic ones included: a
    // face's box holds much empty space (holes, the inside of a curved face),
    // and a short segment inside a part meets the boxes of many large faces.
    if (f.first_triangle == f.end_triangle) {
      m.candidates.push_back({face, -1});
      boxes.push_back(f.box);
    } else {
      for (int t = f.first_triangle; t < f.end_triangle; ++t) {
        m.candidates.push_back({face, t});
        boxes.push_back(triangle_box(m.triangles[t], m.triangles[t].deviation + m.tolerance));
      }
    }
    try {
      f.boundary = boundary_curves(f.face);
    } catch (const Standard_Failure&) {
      f.boundary.clear();  // project() then falls back on BRepExtrema near the boundary
    }
  }
  m.candidate_tree = BoxTree(boxes);
  m.occupied = OccupancyGrid(m.box, boxes);
  if (untessellated > 0) {
    m.log.push_back(std::to_string(untessellated) +
                    " face(s) without a tessellation: intersected by OpenCASCADE only");
  }
}

}  // namespace rdmesh::cad
