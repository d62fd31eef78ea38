// TriangleMeshOracle's sharp features: sharp edges, corners, and the curves
// chaining sharp edges between corners (see the header's file comment).
//
// The sharp edges form a graph on the mesh vertices. Its vertices of degree
// other than 2, and those where the chain turns by more than the feature angle
// (a kink), are corners; walking from each corner along each of its unvisited
// edges, through degree-2 vertices, until the next corner gives the open curves;
// what is left are loops, the closed curves. A walk that comes back to the corner
// it started from would be an open curve with equal ends (a closed polyline with
// a corner): its middle vertex is made a corner too and the walks are redone.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "rdmesh/errors.h"
#include "rdmesh/triangle_mesh_oracle.h"

namespace rdmesh {
namespace {

struct SharpEdge {
  int u, v;         // vertex ids
  int left, right;  // the triangles on both sides
};

struct Walk {
  std::vector<int> vertices;
  int first_edge;
};

}  // namespace

TriangleMeshOracle::EdgeFlags TriangleMeshOracle::sharp_edges(
    const std::vector<std::array<int, 3>>& neighbors) const {
  const int n = static_cast<int>(mesh_.triangles.size());
  std::vector<Point3> normals(n);
  for (int t = 0; t < n; ++t) {
    const auto& tri = mesh_.triangles[t];
    const Point3 nn = cross(mesh_.points[tri[1]] - mesh_.points[tri[0]],
                            mesh_.points[tri[2]] - mesh_.points[tri[0]]);
    normals[t] = (1 / norm(nn)) * nn;
  }
  const double limit = std::cos(options_.feature_angle_degrees * std::numbers::pi / 180);
  EdgeFlags sharp(n, {false, false, false});
  for (int t = 0; t < n; ++t) {
    for (int k = 0; k < 3; ++k) {
      const int u = neighbors[t][k];
      // A border edge (surface-only input) is a feature: the mesh's border follows it.
      sharp[t][k] = u >= 0 ? dot(normals[t], normals[u]) < limit : options_.surface_only;
    }
  }
  return sharp;
}

void TriangleMeshOracle::build_features(const std::vector<std::array<int, 3>>& neighbors,
                                        const EdgeFlags& sharp) {
  const int n = static_cast<int>(mesh_.triangles.size());
  std::vector<SharpEdge> edges;
  for (int t = 0; t < n; ++t) {
    for (int k = 0; k < 3; ++k) {
      const int u = neighbors[t][k];
      if (sharp[t][k] && (u < 0 || t < u)) {
        edges.push_back({mesh_.triangles[t][k], mesh_.triangles[t][(k + 1) % 3], t, u < 0 ? t : u});
      }
    }
  }
  sharp_edge_count_ = static_cast<int>(edges.size());
  const int nv = static_cast<int>(mesh_.points.size());
  std::vector<std::vector<int>> incident(nv);  // edge ids, ascending
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    incident[edges[e].u].push_back(e);
    incident[edges[e].v].push_back(e);
  }
  std::vector<char> is_corner(nv, 0);
  auto other = [&](int e, int v) { return edges[e].u == v ? edges[e].v : edges[e].u; };
  // A curve is smooth: where a chain of two sharp edges turns by more than the
  // feature angle (a kink) it is split, the vertex is a corner.
  const double kink = std::cos(options_.feature_angle_degrees * std::numbers::pi / 180);
  for (int v = 0; v < nv; ++v) {
    is_corner[v] = !incident[v].empty() && incident[v].size() != 2;
    if (incident[v].size() != 2) continue;
    const Point3 p = mesh_.points[v];
    const Point3 in = p - mesh_.points[other(incident[v][0], v)];
    const Point3 out = mesh_.points[other(incident[v][1], v)] - p;
    is_corner[v] = dot(in, out) < kink * norm(in) * norm(out);
  }
  std::vector<Walk> open, loops;
  for (bool again = true; again;) {
    again = false;
    open.clear();
    loops.clear();
    std::vector<char> visited(edges.size(), 0);
    auto walk = [&](int start, int e0) {
      Walk w{{start}, e0};
      int v = start, e = e0;
      for (;;) {
        visited[e] = 1;
        v = other(e, v);
        w.vertices.push_back(v);
        if (is_corner[v] || v == start) break;
        e = incident[v][0] == e ? incident[v][1] : incident[v][0];
      }
      return w;
    };
    for (int v = 0; v < nv; ++v) {
      if (!is_corner[v]) continue;
      for (int e : incident[v]) {
        if (!visited[e]) open.push_back(walk(v, e));
      }
    }
    for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
      if (!visited[e]) loops.push_back(walk(std::min(edges[e].u, edges[e].v), e));
    }
    for (const Walk& w : open) {
      if (w.vertices.front() == w.vertices.back()) {  // a loop through one corner: split it
        is_corner[w.vertices[w.vertices.size() / 2]] = 1;
        again = true;
      }
    }
  }
  // Corners in vertex order.
  std::vector<int> corner_of(nv, 0);
  for (int v = 0; v < nv; ++v) {
    if (!is_corner[v]) continue;
    corner_of[v] = features_.add_corner(mesh_.points[v]).id.value;
  }
  auto add_curve = [&](const Walk& w, bool closed) {
    std::vector<Point3> points;
    for (int v : w.vertices) points.push_back(mesh_.points[v]);
    auto queries = std::make_unique<PolylineCurve>(std::move(points));
    const SharpEdge& e = edges[w.first_edge];
    std::vector<PatchId> patches = {triangle_patch_[e.left], triangle_patch_[e.right]};
    std::sort(patches.begin(), patches.end());
    patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
    CurveInfo info;
    info.id = features_.next_curve_id();
    info.name = "curve_" + std::to_string(info.id.value);
    info.closed = closed;
    info.t_begin = queries->t_begin();
    info.t_end = queries->t_end();
    info.start = CornerId(closed ? 0 : corner_of[w.vertices.front()]);
    info.end = CornerId(closed ? 0 : corner_of[w.vertices.back()]);
    info.patches = patches;
    if (!closed) {
      for (CornerId c : {info.start, info.end}) {
        CornerInfo& corner = features_.corner(c);
        corner.curves.push_back(info.id);
        corner.patches.insert(corner.patches.end(), patches.begin(), patches.end());
      }
    }
    features_.add_curve(std::move(info), std::move(queries));
  };
  for (const Walk& w : open) add_curve(w, false);
  for (const Walk& w : loops) add_curve(w, true);
  for (CornerInfo& c : features_.corners()) {
    for (auto* list : {&c.patches}) {
      std::sort(list->begin(), list->end());
      list->erase(std::unique(list->begin(), list->end()), list->end());
    }
    std::sort(c.curves.begin(), c.curves.end());
    c.curves.erase(std::unique(c.curves.begin(), c.curves.end()), c.curves.end());
  }
}

}  // namespace rdmesh
