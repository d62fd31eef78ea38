// Initial points on each face: interior points of a coarse BRepMesh
// tessellation's triangles, taken in the face's (u, v) domain and evaluated on
// the true surface. The tessellation only chooses where to look.
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <algorithm>
#include <gp_Pnt2d.hxx>

#include "cad_model.h"

namespace rdmesh::cad {
namespace {

Point3 evaluate(const FacePatch& f, double u, double v) {
  const gp_Pnt p = f.surface->Value(u, v);
  return {p.X(), p.Y(), p.Z()};
}

bool inside(const FacePatch& f, double u, double v) {
  return f.classifier->Perform(gp_Pnt2d(u, v)) == TopAbs_IN;
}

std::vector<Point3> from_triangulation(const FacePatch& f) {
  std::vector<Point3> out;
  TopLoc_Location loc;
  const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(f.face, loc);
  if (tri.IsNull() || !tri->HasUVNodes() || tri->NbTriangles() == 0) return out;
  // Centroids of up to kMaxSeeds spread triangles; three interior points per
  // triangle when the face has fewer than three triangles.
  constexpr int kMaxSeeds = 48;
  const int n = tri->NbTriangles();
  const int picks = std::min(n, kMaxSeeds);
  constexpr double kBary[4][3] = {{1.0 / 3, 1.0 / 3, 1.0 / 3},
                                  {4.0 / 6, 1.0 / 6, 1.0 / 6},
                                  {1.0 / 6, 4.0 / 6, 1.0 / 6},
                                  {1.0 / 6, 1.0 / 6, 4.0 / 6}};
  const int first = n >= 3 ? 0 : 1, last = n >= 3 ? 1 : 4;
  for (int k = 0; k < picks; ++k) {
    const int t = 1 + static_cast<int>((static_cast<long long>(k) * n) / picks);
    int a, b, c;
    tri->Triangle(t).Get(a, b, c);
    const gp_Pnt2d pa = tri->UVNode(a), pb = tri->UVNode(b), pc = tri->UVNode(c);
    for (int j = first; j < last; ++j) {
      const double* w = kBary[j];
      const double u = w[0] * pa.X() + w[1] * pb.X() + w[2] * pc.X();
      const double v = w[0] * pa.Y() + w[1] * pb.Y() + w[2] * pc.Y();
      if (inside(f, u, v)) out.push_back(evaluate(f, u, v));
    }
  }
  return out;
}

std::vector<Point3> from_grid(const FacePatch& f) {
  std::vector<Point3> out;
  constexpr int kGrid = 24;
  for (int i = 1; i < kGrid && out.size() < 12; ++i) {
    for (int j = 1; j < kGrid && out.size() < 12; ++j) {
      const double u = f.u0 + (f.u1 - f.u0) * (i * 7 % kGrid) / kGrid;
      const double v = f.v0 + (f.v1 - f.v0) * (j * 11 % kGrid) / kGrid;
      if (inside(f, u, v)) out.push_back(evaluate(f, u, v));
    }
  }
  return out;
}

}  // namespace

void compute_seeds(CadOracle::Model& m) {
  const double deflection = 0.02 * m.box.diagonal();
  BRepMesh_IncrementalMesh mesher(m.shape, deflection, false, 0.5, false);
  m.seeds.assign(m.faces.size(), {});
  int thin = 0;
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    std::vector<Point3> pts = from_triangulation(m.faces[i]);
    if (pts.size() < 3) {
      std::vector<Point3> more = from_grid(m.faces[i]);
      pts.insert(pts.end(), more.begin(), more.end());
    }
    if (pts.size() < 3) ++thin;
    m.seeds[i] = std::move(pts);
  }
  if (thin > 0) {
    m.log.push_back(std::to_string(thin) + " face(s) with fewer than 3 initial points");
  }
}

}  // namespace rdmesh::cad
