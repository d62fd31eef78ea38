// Initial points on each face: centroids of the face's own (u, v) tessellation
// (the accelerator's, face_tessellation.h) that its cells place inside the
// face, evaluated on the true surface. The tessellation only chooses where to
// look. Few points suffice: RR-7912 starts from three per patch and rules
// R3-R4 add what the surface needs; every seed stays a vertex of the mesh, so a
// dense seeding only makes the mesh finer where nothing asked for it.
#include <algorithm>
#include <array>

#include "cad_model.h"

namespace rdmesh::cad {
namespace {

// Per face; a model of few faces (a torus: one face, no curve, no corner) gets
// up to kModelSeeds in all, so that the points span its volume.
constexpr std::size_t kMaxSeeds = 6, kModelSeeds = 48;

Point3 evaluate(const FacePatch& f, double u, double v) {
  const gp_Pnt p = f.surface->Value(u, v);
  return {p.X(), p.Y(), p.Z()};
}

bool classified_inside(const FacePatch& f, double u, double v) {
  return f.cells.classify(
             u, v, [&]() -> const BRepTopAdaptor_FClass2d& { return *f.classifier; }) == TopAbs_IN;
}

/// Up to max_seeds points spread over the face's triangles (their order
/// follows the cells' kd-tree, so spread indices are spread in space):
/// centroids the cells call inside, away from poles, first; then any centroid
/// inside the face.
std::vector<Point3> from_tessellation(const CadOracle::Model& m, const FacePatch& f,
                                      std::size_t max_seeds) {
  std::vector<std::array<double, 2>> sure, unsure;
  for (int t = f.first_triangle; t < f.end_triangle; ++t) {
    const SurfaceTriangle& s = m.triangles[t];
    const double u = (s.uv[0][0] + s.uv[1][0] + s.uv[2][0]) / 3;
    const double v = (s.uv[0][1] + s.uv[1][1] + s.uv[2][1]) / 3;
    UvState state = f.cells.state_at(u, v);
    if (state == UvState::inside && f.cells.near_pole(u, v)) state = UvState::boundary;
    if (state == UvState::inside) sure.push_back({u, v});
    if (state == UvState::boundary) unsure.push_back({u, v});
  }
  std::vector<Point3> out;
  auto spread = [&](const std::vector<std::array<double, 2>>& uv, bool check) {
    const std::size_t n = uv.size();
    if (n == 0) return;
    // Every candidate when few are needed from few; else evenly spaced ones.
    const std::size_t tries = check ? n : std::min(n, max_seeds);
    for (std::size_t k = 0; k < tries && out.size() < max_seeds; ++k) {
      const std::size_t i = check ? k : (k * n) / tries;
      if (check && !classified_inside(f, uv[i][0], uv[i][1])) continue;
      out.push_back(evaluate(f, uv[i][0], uv[i][1]));
    }
  };
  spread(sure, false);
  if (out.size() < 3) spread(unsure, true);
  return out;
}

std::vector<Point3> from_grid(const FacePatch& f) {
  std::vector<Point3> out;
  constexpr int kGrid = 24;
  for (int i = 1; i < kGrid && out.size() < 12; ++i) {
    for (int j = 1; j < kGrid && out.size() < 12; ++j) {
      const double u = f.u0 + (f.u1 - f.u0) * (i * 7 % kGrid) / kGrid;
      const double v = f.v0 + (f.v1 - f.v0) * (j * 11 % kGrid) / kGrid;
      if (classified_inside(f, u, v)) out.push_back(evaluate(f, u, v));
    }
  }
  return out;
}

}  // namespace

void compute_seeds(CadOracle::Model& m) {
  m.features.set_patch_count(m.faces.size());
  const std::size_t max_seeds =
      std::max(kMaxSeeds, kModelSeeds / std::max<std::size_t>(1, m.faces.size()));
  int thin = 0;
  for (std::size_t i = 0; i < m.faces.size(); ++i) {
    std::vector<Point3> pts = from_tessellation(m, m.faces[i], max_seeds);
    if (pts.size() < 3) {
      std::vector<Point3> more = from_grid(m.faces[i]);
      pts.insert(pts.end(), more.begin(), more.end());
    }
    if (pts.size() < 3) ++thin;
    m.features.add_initial_points(PatchId(static_cast<int>(i) + 1), pts);
  }
  if (thin > 0) {
    m.log.push_back(std::to_string(thin) + " face(s) with fewer than 3 initial points");
  }
}

}  // namespace rdmesh::cad
