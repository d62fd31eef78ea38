// Edge adjacency, components and consistent orientation of triangle meshes.
#include <algorithm>
#include <sstream>

#include "rdmesh/errors.h"
#include "rdmesh/triangle_mesh_check.h"

namespace rdmesh {
namespace {

std::string str(const Point3& p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x << " " << p.y << " " << p.z << ")";
  return s.str();
}

struct HalfEdge {
  int lo, hi;    // sorted vertex ids of the edge
  int tri, k;    // edge k of triangle tri
  bool forward;  // traversed lo -> hi by the triangle
  auto key() const { return std::make_pair(lo, hi); }
};

std::vector<HalfEdge> half_edges(const TriangleSoup& soup) {
  std::vector<HalfEdge> h;
  h.reserve(3 * soup.triangles.size());
  for (int t = 0; t < static_cast<int>(soup.triangles.size()); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int u = soup.triangles[t][k], v = soup.triangles[t][(k + 1) % 3];
      h.push_back({std::min(u, v), std::max(u, v), t, k, u < v});
    }
  }
  std::sort(h.begin(), h.end(), [](const HalfEdge& a, const HalfEdge& b) {
    return std::tie(a.lo, a.hi, a.tri, a.k) < std::tie(b.lo, b.hi, b.tri, b.k);
  });
  return h;
}

}  // namespace

OrientationResult try_orient_triangle_mesh(TriangleSoup& soup, bool require_closed) {
  const int n = static_cast<int>(soup.triangles.size());
  OrientationResult result;
  TriangleMeshTopology& topo = result.topology;
  auto fail = [&result](OrientationFailure failure, std::string problem) {
    result.failure = failure;
    result.problem = std::move(problem);
    result.topology = {};
    return result;
  };
  topo.neighbors.assign(n, {-1, -1, -1});
  std::vector<HalfEdge> h = half_edges(soup);
  // same[t][k]: the neighbor traverses the shared edge in the same direction.
  std::vector<std::array<bool, 3>> same(n, {false, false, false});
  std::size_t borders = 0;
  const HalfEdge* first_border = nullptr;
  for (std::size_t i = 0; i < h.size();) {
    std::size_t j = i;
    while (j < h.size() && h[j].key() == h[i].key()) ++j;
    if (j - i > 2) {
      return fail(OrientationFailure::non_manifold_edge,
                  "non-manifold edge " + str(soup.points[h[i].lo]) + " - " +
                      str(soup.points[h[i].hi]) + " shared by " + std::to_string(j - i) +
                      " triangles");
    }
    if (j - i == 1) {
      ++borders;
      if (!first_border) first_border = &h[i];
    } else {
      const HalfEdge &a = h[i], &b = h[i + 1];
      topo.neighbors[a.tri][a.k] = b.tri;
      topo.neighbors[b.tri][b.k] = a.tri;
      same[a.tri][a.k] = same[b.tri][b.k] = a.forward == b.forward;
    }
    i = j;
  }
  if (require_closed && borders > 0) {
    return fail(OrientationFailure::not_closed, "not closed: " + std::to_string(borders) +
                                                    " border edges, e.g. " +
                                                    str(soup.points[first_border->lo]) + " - " +
                                                    str(soup.points[first_border->hi]));
  }
  // Breadth-first orientation of each component.
  topo.component.assign(n, -1);
  std::vector<char> flip(n, 0);
  std::vector<int> queue;
  for (int seed = 0; seed < n; ++seed) {
    if (topo.component[seed] >= 0) continue;
    const int c = topo.component_count++;
    bool closed = true;
    double volume = 0;
    queue.assign(1, seed);
    topo.component[seed] = c;
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const int t = queue[q];
      for (int k = 0; k < 3; ++k) {
        const int u = topo.neighbors[t][k];
        if (u < 0) {
          closed = false;
          continue;
        }
        const char want = flip[t] ^ static_cast<char>(same[t][k]);
        if (topo.component[u] < 0) {
          topo.component[u] = c;
          flip[u] = want;
          queue.push_back(u);
        } else if (flip[u] != want) {
          return fail(
              OrientationFailure::non_orientable,
              "non-orientable surface (a Moebius-like band) around triangle " + std::to_string(t));
        }
      }
      const auto& tri = soup.triangles[t];
      const Point3 &p = soup.points[tri[0]], &a = soup.points[tri[1]], &b = soup.points[tri[2]];
      volume += (flip[t] ? -1.0 : 1.0) * dot(p, cross(a, b)) / 6;
    }
    topo.component_closed.push_back(closed);
    if (closed && volume < 0) {
      for (int t : queue) flip[t] ^= 1;
    }
  }
  bool flipped = false;
  for (int t = 0; t < n; ++t) {
    if (flip[t]) {
      std::swap(soup.triangles[t][1], soup.triangles[t][2]);
      flipped = true;
    }
  }
  if (flipped) {  // edge k of a flipped triangle moved: rebuild the adjacency
    for (auto& nb : topo.neighbors) nb = {-1, -1, -1};
    h = half_edges(soup);
    for (std::size_t i = 0; i + 1 < h.size(); ++i) {
      if (h[i].key() != h[i + 1].key()) continue;
      topo.neighbors[h[i].tri][h[i].k] = h[i + 1].tri;
      topo.neighbors[h[i + 1].tri][h[i + 1].k] = h[i].tri;
      ++i;
    }
  }
  return result;
}

TriangleMeshTopology orient_triangle_mesh(TriangleSoup& soup, const std::string& file,
                                          bool require_closed) {
  OrientationResult result = try_orient_triangle_mesh(soup, require_closed);
  if (!result.ok()) throw InputError(file, result.problem);
  return std::move(result.topology);
}

double enclosed_volume(const TriangleSoup& soup) {
  double v = 0;
  for (const auto& t : soup.triangles) {
    v += dot(soup.points[t[0]], cross(soup.points[t[1]], soup.points[t[2]]));
  }
  return v / 6;
}

}  // namespace rdmesh
