// Output: the cells of D|O (label != 0), the facets of D|S (restricted
// facets), each facet once, oriented towards its side of smaller label, and
// the edges of D|L in curve order with the corners.
#include "refiner.h"

namespace rdmesh::detail {

TetMesh Refiner::extract_mesh() {
  TetMesh mesh;
  mesh.subdomains = oracle_.subdomains();
  mesh.patches = oracle_.patches();
  for (auto v = tr_.finite_vertices_begin(); v != tr_.finite_vertices_end(); ++v) v->info().index = -1;

  auto index_of = [&](Vertex_handle v) {
    int& idx = v->info().index;
    if (idx < 0) {
      idx = static_cast<int>(mesh.vertices.size());
      mesh.vertices.push_back(to_point3(v->point()));
    }
    return idx;
  };

  for (auto c = tr_.finite_cells_begin(); c != tr_.finite_cells_end(); ++c) {
    const int label = c->info().label;
    if (label == kOutside.value) continue;
    // CGAL cells are positively oriented: det(v1-v0, v2-v0, v3-v0) > 0.
    mesh.tets.push_back({index_of(c->vertex(0)), index_of(c->vertex(1)), index_of(c->vertex(2)),
                         index_of(c->vertex(3))});
    mesh.tet_subdomain.push_back(SubdomainId{label});
    for (int i = 0; i < 4; ++i) {
      const int patch = c->info().facet_patch[i];
      // A restricted facet separates two labels; emit it from the larger one.
      if (patch == 0 || c->neighbor(i)->info().label > label) continue;
      Vertex_handle a = c->vertex((i + 1) & 3), b = c->vertex((i + 2) & 3),
                    d = c->vertex((i + 3) & 3);
      // Normal (b-a) x (d-a) must point away from this cell's vertex i.
      if (CGAL::orientation(a->point().point(), b->point().point(), d->point().point(),
                            c->vertex(i)->point().point()) == CGAL::POSITIVE) {
        std::swap(b, d);
      }
      mesh.triangles.push_back({index_of(a), index_of(b), index_of(d)});
      mesh.triangle_patch.push_back(PatchId{patch});
    }
  }
  extract_features(mesh);
  return mesh;
}

void Refiner::extract_features(TetMesh& mesh) {
  mesh.curves = oracle_.curves();
  mesh.corners = corners_;
  for (std::size_t i = 0; i < corner_vertices_.size(); ++i) {
    const int index = corner_vertices_[i]->info().index;
    if (index < 0) continue;  // not in any tetrahedron: reported by the tests/report
    mesh.corner_vertices.push_back(index);
    mesh.corner_ids.push_back(CornerId{static_cast<int>(i) + 1});
  }
  for (CurveState& c : curves_) {
    for (auto a = c.samples.begin(); c.has_next(a); ++a) {
      const int i0 = a->second.vertex->info().index;
      const int i1 = std::next(a)->second.vertex->info().index;
      if (i0 < 0 || i1 < 0) {
        ++stats_.unmeshed_feature_edges;
        continue;
      }
      mesh.edges.push_back({i0, i1});
      mesh.edge_curve.push_back(c.info.id);
    }
  }
}

}  // namespace rdmesh::detail
