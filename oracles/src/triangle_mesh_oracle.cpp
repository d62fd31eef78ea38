// TriangleMeshOracle: construction (validation, orientation, subdomains,
// patches) and the queries that need no geometry predicate. Geometric queries
// are in triangle_mesh_queries.cpp, curves and corners in triangle_mesh_features.cpp.
#include "rdmesh/triangle_mesh_oracle.h"

#include <algorithm>
#include <numeric>

#include "rdmesh/box_tree.h"
#include "rdmesh/errors.h"
#include "rdmesh/number_text.h"
#include "rdmesh/triangle_mesh_check.h"

namespace rdmesh {

TriangleMeshOracle::TriangleMeshOracle(TriangleSoup soup, const std::string& file,
                                       TriangleMeshOptions options)
    : mesh_(std::move(soup)), options_(options), file_(file) {
  if (!(options_.feature_angle_degrees >= 0 && options_.feature_angle_degrees <= 180)) {
    throw InputError(file, "feature angle " + short_number(options_.feature_angle_degrees) +
                               " is not in [0, 180] degrees");
  }
  validate_soup(mesh_, file);
  const TriangleMeshTopology topo =
      orient_triangle_mesh(mesh_, file, /*require_closed=*/!options_.surface_only);
  if (!options_.surface_only && topo.component_count > kMaxComponents) {
    throw InputError(file, std::to_string(topo.component_count) + " closed components (at most " +
                               std::to_string(kMaxComponents) + ")");
  }
  if (options_.check_self_intersections) check_self_intersections(mesh_, file);
  mesh_box_ = {mesh_.points[0], mesh_.points[0]};
  for (const Point3& p : mesh_.points) {
    mesh_box_.lo = {std::min(mesh_box_.lo.x, p.x), std::min(mesh_box_.lo.y, p.y),
                    std::min(mesh_box_.lo.z, p.z)};
    mesh_box_.hi = {std::max(mesh_box_.hi.x, p.x), std::max(mesh_box_.hi.y, p.y),
                    std::max(mesh_box_.hi.z, p.z)};
  }
  const double diag = mesh_box_.diagonal();
  const Point3 margin{0.01 * diag, 0.01 * diag, 0.01 * diag};
  box_ = {mesh_box_.lo - margin, mesh_box_.hi + margin};
  tolerance_ = 1e-10 * diag;
  bvh_ = std::make_unique<BoxTree>(mesh_.points, mesh_.triangles);
  triangle_component_ = topo.component;
  if (options_.surface_only) {
    component_parent_.assign(topo.component_count, -1);  // no subdomain, no nesting
  } else {
    build_subdomains(topo.component_count);
  }
  const EdgeFlags sharp = sharp_edges(topo.neighbors);
  build_patches(topo.neighbors, sharp);
  build_features(topo.neighbors, sharp);
  build_curvature();
}

TriangleMeshOracle::~TriangleMeshOracle() = default;

std::unique_ptr<TriangleMeshOracle> TriangleMeshOracle::from_file(const std::string& path,
                                                                  TriangleMeshOptions options) {
  return std::make_unique<TriangleMeshOracle>(read_triangle_mesh(path), path, options);
}

void TriangleMeshOracle::build_subdomains(int count) {
  // Volume of each component (outward oriented, so positive), about its first vertex.
  component_volume_.assign(count, 0.0);
  std::vector<int> first_vertex(count, -1);
  for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
    const int c = triangle_component_[t];
    const auto& tri = mesh_.triangles[t];
    if (first_vertex[c] < 0) first_vertex[c] = tri[0];
    const Point3 o = mesh_.points[first_vertex[c]];
    component_volume_[c] +=
        dot(mesh_.points[tri[0]] - o, cross(mesh_.points[tri[1]] - o, mesh_.points[tri[2]] - o)) /
        6;
  }
  // Containment: which components contain a vertex of component c.
  std::vector<std::vector<int>> containers(count);
  unsigned char inside[kMaxComponents];
  for (int c = 0; c < count && count > 1; ++c) {
    const Point3 p = mesh_.points[first_vertex[c]];
    bool ok = false;
    for (int dir = 0; dir < 12 && !ok; ++dir) ok = ray_parity(p, dir, c, false, inside);
    if (!ok) ray_parity(p, 0, c, true, inside);
    for (int k = 0; k < count; ++k) {
      if (k != c && inside[k]) containers[c].push_back(k);
    }
  }
  component_depth_.assign(count, 0);
  component_parent_.assign(count, -1);
  for (int c = 0; c < count; ++c) component_depth_[c] = static_cast<int>(containers[c].size());
  volume_ = 0;
  for (int c = 0; c < count; ++c) {
    for (int k : containers[c]) {
      if (component_depth_[k] == component_depth_[c] - 1) component_parent_[c] = k;
    }
    if (component_depth_[c] == 0) volume_ += component_volume_[c];
    subdomain_infos_.push_back({SubdomainId(c + 1), "subdomain_" + std::to_string(c + 1)});
  }
}

void TriangleMeshOracle::build_patches(const std::vector<std::array<int, 3>>& neighbors,
                                       const EdgeFlags& sharp) {
  const int n = static_cast<int>(mesh_.triangles.size());
  triangle_patch_.assign(n, PatchId(0));
  std::vector<int> stack;
  for (int seed = 0; seed < n; ++seed) {
    if (triangle_patch_[seed].value != 0) continue;
    const PatchId id(static_cast<int>(patch_infos_.size()) + 1);
    std::vector<int> members;
    triangle_patch_[seed] = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      members.push_back(t);
      for (int k = 0; k < 3; ++k) {
        const int u = neighbors[t][k];
        if (u >= 0 && !sharp[t][k] && triangle_patch_[u].value == 0) {
          triangle_patch_[u] = id;
          stack.push_back(u);
        }
      }
    }
    std::sort(members.begin(), members.end());
    const int c = triangle_component_[seed];
    const int outer = component_parent_[c] + 1, inner = options_.surface_only ? 0 : c + 1;
    patch_infos_.push_back({id, "patch_" + std::to_string(id.value),
                            SubdomainId(std::min(outer, inner)),
                            SubdomainId(std::max(outer, inner))});
    patch_triangles_.push_back(std::move(members));
  }
  features_.set_patch_count(patch_triangles_.size());
  for (std::size_t i = 0; i < patch_triangles_.size(); ++i) {
    features_.add_initial_points(PatchId(static_cast<int>(i) + 1), points_on(patch_triangles_[i]));
  }
}

std::vector<Point3> TriangleMeshOracle::points_on(const std::vector<int>& tris) const {
  std::vector<Point3> points;
  const std::size_t count = std::min<std::size_t>(8, tris.size());
  for (std::size_t i = 0; i < count; ++i) {
    const auto& t = mesh_.triangles[tris[i * tris.size() / count]];
    const Point3 &a = mesh_.points[t[0]], &b = mesh_.points[t[1]], &c = mesh_.points[t[2]];
    const Point3 g = (1.0 / 3) * (a + b + c);
    points.push_back(g);
    if (count < 3) {  // a tiny patch: points between the centroid and the corners too
      for (const Point3& v : {a, b}) points.push_back(0.5 * (g + v));
    }
  }
  return points;
}

}  // namespace rdmesh
