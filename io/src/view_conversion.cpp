#include "rdmesh/view_conversion.h"

namespace rdmesh {
namespace {

template <class Id>
std::vector<int> values(const std::vector<Id>& ids) {
  std::vector<int> out;
  out.reserve(ids.size());
  for (const Id& id : ids) out.push_back(id.value);
  return out;
}

}  // namespace

view::ViewMesh to_view_mesh(const TetMesh& mesh) {
  view::ViewMesh v;
  v.points = mesh.vertices;
  v.tets = mesh.tets;
  v.tet_labels = values(mesh.tet_subdomain);
  v.triangles = mesh.triangles;
  v.triangle_labels = values(mesh.triangle_patch);
  v.edges = mesh.edges;
  v.edge_labels = values(mesh.edge_curve);
  v.corners = mesh.corner_vertices;
  for (const SubdomainInfo& s : mesh.subdomains) {
    if (!s.name.empty()) v.subdomain_names[s.id.value] = s.name;
  }
  return v;
}

}  // namespace rdmesh
