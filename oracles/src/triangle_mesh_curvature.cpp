// TriangleMeshOracle's discrete curvature (see curvature() in
// rdmesh/triangle_mesh_oracle.h): per patch, vertex normals and the largest
// normal curvature towards a neighbour, interpolated over the nearest triangle.
#include <algorithm>
#include <cmath>

#include "rdmesh/box_tree.h"
#include "rdmesh/triangle_mesh_oracle.h"

namespace rdmesh {

void TriangleMeshOracle::build_curvature() {
  corner_curvature_.assign(mesh_.triangles.size(), {0.0, 0.0, 0.0});
  for (const std::vector<int>& tris : patch_triangles_) {
    std::vector<int> verts;
    for (int t : tris)
      verts.insert(verts.end(), mesh_.triangles[t].begin(), mesh_.triangles[t].end());
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    auto index = [&verts](int v) {
      return static_cast<std::size_t>(std::lower_bound(verts.begin(), verts.end(), v) -
                                      verts.begin());
    };
    // Angle-weighted vertex normals over the patch's triangles.
    std::vector<Point3> normal(verts.size(), Point3{0, 0, 0});
    for (int t : tris) {
      const auto& tri = mesh_.triangles[t];
      const Point3 n = cross(mesh_.points[tri[1]] - mesh_.points[tri[0]],
                             mesh_.points[tri[2]] - mesh_.points[tri[0]]);
      const double nn = norm(n);
      if (!(nn > 0)) continue;
      for (int k = 0; k < 3; ++k) {
        const Point3 a = mesh_.points[tri[(k + 1) % 3]] - mesh_.points[tri[k]];
        const Point3 b = mesh_.points[tri[(k + 2) % 3]] - mesh_.points[tri[k]];
        const double angle = std::atan2(norm(cross(a, b)), dot(a, b));
        normal[index(tri[k])] = normal[index(tri[k])] + (angle / nn) * n;
      }
    }
    for (Point3& n : normal) {
      const double len = norm(n);
      if (len > 0) n = (1 / len) * n;
    }
    // The largest normal curvature towards a neighbour, over the patch's edges.
    std::vector<double> kappa(verts.size(), 0.0);
    for (int t : tris) {
      const auto& tri = mesh_.triangles[t];
      for (int k = 0; k < 3; ++k) {
        for (int j : {(k + 1) % 3, (k + 2) % 3}) {
          const std::size_t v = index(tri[k]);
          const Point3 d = mesh_.points[tri[j]] - mesh_.points[tri[k]];
          const double dd = squared_norm(d);
          if (dd > 0) kappa[v] = std::max(kappa[v], std::fabs(2 * dot(normal[v], d)) / dd);
        }
      }
    }
    for (int t : tris) {
      for (int k = 0; k < 3; ++k) corner_curvature_[t][k] = kappa[index(mesh_.triangles[t][k])];
    }
  }
}

std::optional<double> TriangleMeshOracle::curvature(const Point3& x, PatchId patch) const {
  if (patch.value < 1 || patch.value > static_cast<int>(patch_infos_.size())) return std::nullopt;
  double best = HUGE_VAL;
  int best_t = -1;
  Point3 foot;
  bvh_->nearest([&](const Box3& box) { return squared_distance(box, x); },
                [&](int t, double& bound) {
                  if (triangle_patch_[t] != patch) return;
                  const auto& tri = mesh_.triangles[t];
                  const Point3 y = closest_on_triangle(x, mesh_.points[tri[0]],
                                                       mesh_.points[tri[1]], mesh_.points[tri[2]]);
                  const double d2 = squared_norm(y - x);
                  if (d2 < bound) bound = d2, best_t = t, foot = y;
                },
                best);
  if (best_t < 0) return std::nullopt;
  // Barycentric coordinates of the foot in its triangle.
  const auto& tri = mesh_.triangles[best_t];
  const Point3 &a = mesh_.points[tri[0]], &b = mesh_.points[tri[1]], &c = mesh_.points[tri[2]];
  const Point3 n = cross(b - a, c - a);
  const double nn = squared_norm(n);
  const auto& k = corner_curvature_[best_t];
  if (!(nn > 0)) return std::max({k[0], k[1], k[2]});
  const double wa = dot(cross(b - foot, c - foot), n) / nn;
  const double wb = dot(cross(c - foot, a - foot), n) / nn;
  const double wc = 1 - wa - wb;
  return std::max(0.0, wa * k[0] + wb * k[1] + wc * k[2]);
}

}  // namespace rdmesh
