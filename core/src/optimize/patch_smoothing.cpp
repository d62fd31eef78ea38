#include "patch_smoothing.h"

#include <cmath>
#include <limits>

#include "../simplex_geometry.h"
#include "tet_smoothing.h"

namespace rdmesh::detail {
namespace {

/// The triangle (a, b, c)'s vertices with vertex v at p.
std::array<Point3, 3> corners_with(const TetTopology& topo, const std::array<int, 3>& f, int v,
                                   const Point3& p) {
  std::array<Point3, 3> q;
  for (int k = 0; k < 3; ++k) q[k] = f[k] == v ? p : topo.point(f[k]);
  return q;
}

Point3 area_normal(const std::array<Point3, 3>& q) { return cross(q[1] - q[0], q[2] - q[0]); }

}  // namespace

PatchSurface::PatchSurface(const TetMesh& mesh, const DomainOracle& oracle,
                           const ScalarField& facet_distance, const ScalarField& edge_size,
                           const ScalarField& facet_size)
    : oracle_(oracle),
      facet_distance_(facet_distance),
      edge_size_(edge_size),
      facet_size_(facet_size),
      triangles_(mesh.triangles),
      patch_(mesh.vertices.size(), 0),
      feature_(mesh.vertices.size(), 0),
      curves_(oracle.curves()),
      curve_(mesh.vertices.size(), 0),
      chain_(mesh.vertices.size(), {-1, -1}),
      triangles_of_(mesh.vertices.size()) {
  normal0_.reserve(triangles_.size());
  for (std::size_t f = 0; f < triangles_.size(); ++f) {
    const auto& t = triangles_[f];
    const Point3 n = area_normal({mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]});
    const double len = norm(n);
    normal0_.push_back(len > 0 ? (1.0 / len) * n : Point3{0, 0, 0});
    for (const int v : t) {
      triangles_of_[v].push_back(static_cast<int>(f));
      const int patch = mesh.triangle_patch[f].value;
      // -1: on triangles of two patches.
      patch_[v] = patch_[v] == 0 || patch_[v] == patch ? patch : -1;
    }
  }
  for (const PatchId& p : mesh.triangle_patch) triangle_patch_.push_back(p.value);
  // Vertices inside one chain: two feature edges of one curve, no corner.
  std::vector<int> edges_at(mesh.vertices.size(), 0);
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    for (int k = 0; k < 2; ++k) {
      const int v = mesh.edges[e][k], w = mesh.edges[e][1 - k];
      const int c = mesh.edge_curve[e].value;
      if (edges_at[v]++ == 0) {
        curve_[v] = c;
        chain_[v] = {w, -1};
      } else if (curve_[v] == c && edges_at[v] == 2) {
        chain_[v][1] = w;
      } else {
        curve_[v] = -1;
      }
    }
  }
  for (const auto& e : mesh.edges) feature_[e[0]] = feature_[e[1]] = 1;
  for (const int v : mesh.corner_vertices) feature_[v] = 1, curve_[v] = -1;
  for (std::size_t v = 0; v < curve_.size(); ++v) {
    if (edges_at[v] != 2) curve_[v] = 0;
    curve_[v] = std::max(curve_[v], 0);
  }
  for (std::size_t v = 0; v < patch_.size(); ++v) {
    if (feature_[v]) patch_[v] = -1;
  }
  for (int& p : patch_) p = std::max(p, 0);
}

std::optional<Point3> PatchSurface::project(const Point3& p, int patch) const {
  const auto q = oracle_.project(p, PatchId{patch});
  if (!q || !is_finite(*q)) return std::nullopt;
  return q;
}

Point3 PatchSurface::normal_at(const TetTopology& topo, int v, const Point3& p) const {
  Point3 n{0, 0, 0};
  for (const int f : triangles_of_[v]) n = n + area_normal(corners_with(topo, triangles_[f], v, p));
  const double len = norm(n);
  return len > 0 ? (1.0 / len) * n : Point3{0, 0, 0};
}

bool PatchSurface::keeps_normals(const TetTopology& topo, int v, const Point3& p) const {
  const double min_cos = std::cos(kMaxNormalTurnDeg * M_PI / 180);
  for (const int f : triangles_of_[v]) {
    const Point3 n = area_normal(corners_with(topo, triangles_[f], v, p));
    const double len = norm(n);
    if (!(len > 0) || !(dot(n, normal0_[f]) >= min_cos * len)) return false;
  }
  return true;
}

bool PatchSurface::near_surface(const TetTopology& topo, int v, const Point3& p) const {
  int patch = 0;
  const auto gap = [&](const Point3& s) {
    const auto foot = project(s, patch);
    return foot ? distance(*foot, s) : std::numeric_limits<double>::infinity();
  };
  for (const int f : triangles_of_[v]) {
    patch = triangle_patch_[f];
    const auto q = corners_with(topo, triangles_[f], v, p);
    Point3 samples[3] = {(1.0 / 3) * (q[0] + q[1] + q[2]), {}, {}};
    int n = 1;
    for (int k = 0; k < 3; ++k) {
      if (triangles_[f][k] == v) continue;
      samples[n++] = 0.5 * (p + q[k]);
    }
    for (const Point3& s : samples) {
      if (!(gap(s) <= facet_distance_(s))) return false;
    }
    // The circumcentre, where R4 bounds the distance and the size (on no
    // feature vertex): within the facet distance, or no farther than before
    // the move; a circumradius within the facet size, or no larger than before.
    const auto& t = triangles_[f];
    if (feature_[t[0]] || feature_[t[1]] || feature_[t[2]]) continue;
    const auto q0 = corners_with(topo, triangles_[f], v, topo.point(v));
    const Point3 c = triangle_circumcenter(q[0], q[1], q[2]);
    if (const double dc = gap(c); !(dc <= facet_distance_(c))) {
      if (!(dc <= gap(triangle_circumcenter(q0[0], q0[1], q0[2])))) return false;
    }
    if (const double r = distance(c, q[0]); !(r <= facet_size_(c))) {
      if (!(r <= distance(triangle_circumcenter(q0[0], q0[1], q0[2]), q0[0]))) return false;
    }
  }
  return true;
}

bool smooth_on_patch(TetTopology& topo, const PatchSurface& surface, int v) {
  const int patch = surface.patch_of(v);
  if (patch == 0 || topo.tets_of(v).empty()) return false;
  double start = std::numeric_limits<double>::infinity();
  double nearest = std::numeric_limits<double>::infinity();
  for (const int t : topo.tets_of(v)) {
    start = std::min(start, topo.quality(t));
    for (const int w : topo.tet(t)) {
      if (w != v) nearest = std::min(nearest, distance(topo.point(w), topo.point(v)));
    }
  }
  if (!(nearest > 0)) return false;
  const Star star(topo, v);
  Point3 at = topo.point(v);
  double q = start;
  // The positions reached, each better than the one before.
  std::vector<Point3> path;
  // A trial position: projected onto the patch, kept when the star's smallest
  // angle strictly rises and the triangles keep their normals.
  const auto try_at = [&](const Point3& p) {
    // The tangent-plane point first: the projection (the costly query, 1 to
    // 16 us on CAD faces) only for a step that raises the angle before it.
    if (!(star.min_quality(p, q) > q)) return false;
    const auto on = surface.project(p, patch);
    if (!on) return false;
    const double qp = star.min_quality(*on, q);
    if (!(qp > q) || !surface.keeps_normals(topo, v, *on)) return false;
    at = *on;
    q = qp;
    path.push_back(at);
    return true;
  };
  // The ascent direction of the star's worst tetrahedra, in the tangent plane.
  const auto tangent = [&](const Point3& g) {
    const Point3 n = surface.normal_at(topo, v, at);
    return g - dot(g, n) * n;
  };
  ascend(star, at, nearest, tangent, try_at);
  // The last position whose triangles stay within the facet distance (the
  // distance is checked once, not at every step: it costs 9 to 24 projections).
  for (auto p = path.rbegin(); p != path.rend(); ++p) {
    if (surface.near_surface(topo, v, *p)) {
      topo.move(v, *p);
      return true;
    }
  }
  return false;
}

}  // namespace rdmesh::detail
