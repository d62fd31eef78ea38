#include "mesh_labels.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "rdmesh/errors.h"

namespace rdmesh::io_detail {
namespace {

template <std::size_t N>
void check_indices(const std::vector<std::array<int, N>>& elements, std::size_t num_vertices,
                   const char* what) {
  for (std::size_t e = 0; e < elements.size(); ++e) {
    for (int v : elements[e]) {
      if (v < 0 || static_cast<std::size_t>(v) >= num_vertices) {
        throw InternalError(std::string("TetMesh: ") + what + " " + std::to_string(e) +
                            " refers to vertex " + std::to_string(v) + " but the mesh has " +
                            std::to_string(num_vertices) + " vertices");
      }
    }
  }
}

/// Throws unless labels.size() == count and every label is >= 1.
template <class LabelT>
void check_labels(const std::vector<LabelT>& labels, std::size_t count, const char* elements,
                  const char* element, const char* label) {
  if (labels.size() != count) {
    throw InternalError("TetMesh: " + std::to_string(count) + " " + elements + " but " +
                        std::to_string(labels.size()) + " " + label + " labels");
  }
  for (std::size_t e = 0; e < labels.size(); ++e) {
    if (labels[e].value <= 0) {
      throw InternalError("TetMesh: " + std::string(element) + " " + std::to_string(e) + " has " +
                          label + " id " + std::to_string(labels[e].value) + " (ids start at 1)");
    }
  }
}

/// The 1D and 0D levels: edge and corner arrays, their labels, no degenerate
/// edge, no vertex or corner listed twice.
void check_features(const TetMesh& mesh) {
  check_labels(mesh.edge_curve, mesh.edges.size(), "feature edges", "feature edge", "curve");
  check_labels(mesh.corner_ids, mesh.corner_vertices.size(), "corner vertices", "corner vertex",
               "corner");
  check_indices(mesh.edges, mesh.vertices.size(), "feature edge");
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    if (mesh.edges[e][0] == mesh.edges[e][1]) {
      throw InternalError("TetMesh: feature edge " + std::to_string(e) + " joins vertex " +
                          std::to_string(mesh.edges[e][0]) + " to itself");
    }
  }
  std::vector<std::array<int, 1>> corners;
  for (int v : mesh.corner_vertices) corners.push_back({v});
  check_indices(corners, mesh.vertices.size(), "corner vertex");
  std::map<int, std::size_t> vertex_seen, id_seen;
  for (std::size_t c = 0; c < corners.size(); ++c) {
    if (!vertex_seen.emplace(mesh.corner_vertices[c], c).second) {
      throw InternalError("TetMesh: vertex " + std::to_string(mesh.corner_vertices[c]) +
                          " is listed twice in corner_vertices");
    }
    if (!id_seen.emplace(mesh.corner_ids[c].value, c).second) {
      throw InternalError("TetMesh: corner " + std::to_string(mesh.corner_ids[c].value) +
                          " is at two vertices");
    }
  }
}

/// Second order: none of the mid-node arrays, or all of them, one entry per element.
void check_mid_nodes(const TetMesh& mesh) {
  const bool any = !mesh.tet_mid_nodes.empty() || !mesh.triangle_mid_nodes.empty() ||
                   !mesh.edge_mid_nodes.empty();
  if (!any) return;
  if (mesh.tet_mid_nodes.size() != mesh.tets.size() ||
      mesh.triangle_mid_nodes.size() != mesh.triangles.size() ||
      mesh.edge_mid_nodes.size() != mesh.edges.size()) {
    throw InternalError("TetMesh: the mid-node arrays do not match the elements (" +
                        std::to_string(mesh.tet_mid_nodes.size()) + " tets, " +
                        std::to_string(mesh.triangle_mid_nodes.size()) + " triangles, " +
                        std::to_string(mesh.edge_mid_nodes.size()) + " edges)");
  }
  check_indices(mesh.tet_mid_nodes, mesh.vertices.size(), "tet mid nodes of");
  check_indices(mesh.triangle_mid_nodes, mesh.vertices.size(), "triangle mid nodes of");
  std::vector<std::array<int, 1>> edge_nodes;
  for (int v : mesh.edge_mid_nodes) edge_nodes.push_back({v});
  check_indices(edge_nodes, mesh.vertices.size(), "feature edge mid node of");
}

/// Partitioned: one partition >= 1 per element of every kind.
void check_partitions(const TetMesh& mesh) {
  if (mesh.tet_partition.empty() && mesh.triangle_partition.empty() &&
      mesh.edge_partition.empty() && mesh.corner_partition.empty()) {
    return;
  }
  if (mesh.tet_partition.size() != mesh.tets.size() ||
      mesh.triangle_partition.size() != mesh.triangles.size() ||
      mesh.edge_partition.size() != mesh.edges.size() ||
      mesh.corner_partition.size() != mesh.corner_vertices.size()) {
    throw InternalError("TetMesh: the partition arrays do not match the elements");
  }
  for (const auto* block : {&mesh.tet_partition, &mesh.triangle_partition, &mesh.edge_partition,
                            &mesh.corner_partition}) {
    for (int p : *block) {
      if (p < 1)
        throw InternalError("TetMesh: partition " + std::to_string(p) + " (ids start at 1)");
    }
  }
}

std::vector<Label> merge_labels(std::map<int, std::string> named, const std::vector<int>& used) {
  for (int id : used) named.try_emplace(id);
  std::vector<Label> labels;
  labels.reserve(named.size());
  for (auto& [id, name] : named) {
    if (id > 0) labels.push_back({id, name});  // 0 is "outside", never an element label
  }
  return labels;
}

}  // namespace

void check_mesh(const TetMesh& mesh) {
  if (mesh.tet_subdomain.size() != mesh.tets.size()) {
    throw InternalError("TetMesh: " + std::to_string(mesh.tets.size()) + " tets but " +
                        std::to_string(mesh.tet_subdomain.size()) + " subdomain labels");
  }
  if (mesh.triangle_patch.size() != mesh.triangles.size()) {
    throw InternalError("TetMesh: " + std::to_string(mesh.triangles.size()) + " triangles but " +
                        std::to_string(mesh.triangle_patch.size()) + " patch labels");
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Point3& p = mesh.vertices[i];
    if (!is_finite(p)) {
      throw InternalError("TetMesh: vertex " + std::to_string(i) + " has a non-finite coordinate");
    }
  }
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    if (mesh.tet_subdomain[t].value <= 0) {
      throw InternalError("TetMesh: tet " + std::to_string(t) + " has subdomain id " +
                          std::to_string(mesh.tet_subdomain[t].value) + " (ids start at 1)");
    }
  }
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (mesh.triangle_patch[f].value <= 0) {
      throw InternalError("TetMesh: triangle " + std::to_string(f) + " has patch id " +
                          std::to_string(mesh.triangle_patch[f].value) + " (ids start at 1)");
    }
  }
  check_indices(mesh.tets, mesh.vertices.size(), "tet");
  check_indices(mesh.triangles, mesh.vertices.size(), "triangle");
  check_features(mesh);
  check_mid_nodes(mesh);
  check_partitions(mesh);
}

bool has_features(const TetMesh& mesh) {
  return !mesh.edges.empty() || !mesh.corner_vertices.empty() || !mesh.curves.empty() ||
         !mesh.corners.empty();
}

std::vector<int> tet_label_values(const TetMesh& mesh) {
  std::vector<int> v;
  v.reserve(mesh.tet_subdomain.size());
  for (SubdomainId s : mesh.tet_subdomain) v.push_back(s.value);
  return v;
}

std::vector<int> triangle_label_values(const TetMesh& mesh) {
  std::vector<int> v;
  v.reserve(mesh.triangle_patch.size());
  for (PatchId p : mesh.triangle_patch) v.push_back(p.value);
  return v;
}

std::vector<int> edge_label_values(const TetMesh& mesh) {
  std::vector<int> v;
  v.reserve(mesh.edge_curve.size());
  for (CurveId c : mesh.edge_curve) v.push_back(c.value);
  return v;
}

std::vector<int> corner_label_values(const TetMesh& mesh) {
  std::vector<int> v;
  v.reserve(mesh.corner_ids.size());
  for (CornerId c : mesh.corner_ids) v.push_back(c.value);
  return v;
}

std::vector<Label> subdomain_labels(const TetMesh& mesh) {
  std::map<int, std::string> named;
  for (const SubdomainInfo& s : mesh.subdomains) named.emplace(s.id.value, s.name);
  return merge_labels(std::move(named), tet_label_values(mesh));
}

std::vector<Label> patch_labels(const TetMesh& mesh) {
  std::map<int, std::string> named;
  for (const PatchInfo& p : mesh.patches) named.emplace(p.id.value, p.name);
  return merge_labels(std::move(named), triangle_label_values(mesh));
}

std::vector<Label> curve_labels(const TetMesh& mesh) {
  std::map<int, std::string> named;
  for (const CurveInfo& c : mesh.curves) named.emplace(c.id.value, c.name);
  return merge_labels(std::move(named), edge_label_values(mesh));
}

std::vector<Label> corner_labels(const TetMesh& mesh) {
  std::map<int, std::string> named;
  for (const CornerInfo& c : mesh.corners) named.emplace(c.id.value, std::string());
  return merge_labels(std::move(named), corner_label_values(mesh));
}

std::vector<std::vector<int>> group_by_label(const std::vector<int>& element_labels,
                                             const std::vector<Label>& labels) {
  std::vector<std::vector<int>> groups(labels.size());
  for (std::size_t e = 0; e < element_labels.size(); ++e) {
    auto it = std::lower_bound(labels.begin(), labels.end(), element_labels[e],
                               [](const Label& l, int id) { return l.id < id; });
    // Every used label is in `labels` by construction (subdomain_labels/patch_labels).
    groups[static_cast<std::size_t>(it - labels.begin())].push_back(static_cast<int>(e));
  }
  return groups;
}

}  // namespace rdmesh::io_detail
