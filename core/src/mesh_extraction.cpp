// Output: the cells of D|O (label != 0), the facets of D|S (restricted
// facets), each facet once, oriented towards its side of smaller label, and
// the edges of D|L in curve order with the corners. Surface only: the
// restricted facets alone, oriented consistently piece by piece.
#include <atomic>
#include <unordered_map>

#include "rdmesh/parallel_for.h"
#include "rdmesh/triangle_mesh_check.h"
#include "refiner.h"

namespace rdmesh::detail {

TetMesh Refiner::extract_mesh(std::vector<double>* cosines) {
  TetMesh mesh;
  mesh.subdomains = oracle_.subdomains();
  mesh.patches = oracle_.patches();
  for (auto v = tr_.finite_vertices_begin(); v != tr_.finite_vertices_end(); ++v)
    v->info().index = -1;

  auto index_of = [&](Vertex_handle v) {
    int& idx = v->info().index;
    if (idx < 0) {
      idx = static_cast<int>(mesh.vertices.size());
      mesh.vertices.push_back(to_point3(v->point()));
    }
    return idx;
  };

  if (options_.surface_only) {
    extract_surface(mesh, index_of);
    extract_features(mesh);
    return mesh;
  }
  // A restricted facet separates two labels; it is emitted from the larger one.
  auto emits_triangle = [](Cell_handle c, int i, int label) {
    return c->info().facet_patch[i] != kNotRestricted && !(c->neighbor(i)->info().label > label);
  };
  auto in_domain = [this](Cell_handle c) {
    return c->info().label != kOutside.value && !tr_.is_infinite(c);
  };
  // The domain cells in container order, cut into runs of kParallelChunk
  // (where each run starts: bounds that depend on the triangulation alone).
  // The runs are then read on the run's threads, each writing its own part of
  // arrays sized exactly beforehand (grown by doubling, they held up to twice
  // their size, at the run's peak: the triangulation is still alive here).
  std::vector<Triangulation::All_cells_iterator> starts;
  std::size_t tets = 0;
  for (auto c = tr_.all_cells_begin(); c != tr_.all_cells_end(); ++c) {
    if (!in_domain(c)) continue;
    if (tets % kParallelChunk == 0) starts.push_back(c);
    ++tets;
  }
  // Calls body(cell, position) for the domain cells of run k, in order.
  auto for_run = [&](std::size_t k, auto&& body) {
    const std::size_t end = std::min(tets, (k + 1) * kParallelChunk);
    auto c = starts[k];
    for (std::size_t t = k * kParallelChunk; t < end; ++c) {
      if (in_domain(c)) body(Cell_handle(c), t++);
    }
  };
  const int threads = options_.threads;
  // The vertices of domain cells are marked (index -1 -> 0, written by any
  // run that holds one: the same value whoever writes) and each run counts
  // the triangles it emits.
  std::vector<std::size_t> triangle_start(starts.size() + 1, 0);
  parallel_tasks(starts.size(), threads, [&](std::size_t k) {
    std::size_t triangles = 0;
    for_run(k, [&](Cell_handle c, std::size_t) {
      const int label = c->info().label;
      for (int i = 0; i < 4; ++i) {
        std::atomic_ref<int>(c->vertex(i)->info().index).store(0, std::memory_order_relaxed);
        triangles += emits_triangle(c, i, label);
      }
    });
    triangle_start[k + 1] = triangles;
  });
  for (std::size_t k = 0; k < starts.size(); ++k) triangle_start[k + 1] += triangle_start[k];
  // Output vertices in the triangulation's order.
  mesh.vertices.reserve(tr_.number_of_vertices());
  for (auto v = tr_.finite_vertices_begin(); v != tr_.finite_vertices_end(); ++v) {
    if (v->info().index < 0) continue;
    v->info().index = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back(to_point3(v->point()));
  }
  mesh.tets.resize(tets);
  mesh.tet_subdomain.resize(tets);
  if (cosines != nullptr) cosines->resize(tets);
  mesh.triangles.resize(triangle_start.back());
  mesh.triangle_patch.resize(triangle_start.back());
  parallel_tasks(starts.size(), threads, [&](std::size_t k) {
    std::size_t triangle = triangle_start[k];
    for_run(k, [&](Cell_handle c, std::size_t t) {
      const int label = c->info().label;
      // CGAL cells are positively oriented: det(v1-v0, v2-v0, v3-v0) > 0.
      mesh.tets[t] = {c->vertex(0)->info().index, c->vertex(1)->info().index,
                      c->vertex(2)->info().index, c->vertex(3)->info().index};
      mesh.tet_subdomain[t] = SubdomainId{label};
      if (cosines != nullptr) (*cosines)[t] = c->info().shape_cosine;
      for (int i = 0; i < 4; ++i) {
        if (!emits_triangle(c, i, label)) continue;
        Vertex_handle a = c->vertex((i + 1) & 3), b = c->vertex((i + 2) & 3),
                      d = c->vertex((i + 3) & 3);
        // Normal (b-a) x (d-a) must point away from this cell's vertex i.
        if (CGAL::orientation(a->point().point(), b->point().point(), d->point().point(),
                              c->vertex(i)->point().point()) == CGAL::POSITIVE) {
          std::swap(b, d);
        }
        mesh.triangles[triangle] = {a->info().index, b->info().index, d->info().index};
        mesh.triangle_patch[triangle] = c->info().facet_patch[i];
        ++triangle;
      }
    });
  });
  extract_features(mesh);
  return mesh;
}

template <class IndexOf>
void Refiner::extract_surface(TetMesh& mesh, IndexOf& index_of) {
  // Each restricted facet once, from its cell of smaller stamp. (CGAL's
  // facet iterator picks the side by comparing cell addresses: the output
  // then depended on the heap's layout, e.g. from the CLI to Python.)
  for (auto c = tr_.all_cells_begin(); c != tr_.all_cells_end(); ++c) {
    for (int i = 0; i < 4; ++i) {
      const PatchId patch = c->info().facet_patch[i];
      if (patch == kNotRestricted || c->neighbor(i)->info().stamp < c->info().stamp) continue;
      const Vertex_handle a = c->vertex((i + 1) & 3), b = c->vertex((i + 2) & 3),
                          d = c->vertex((i + 3) & 3);
      if (tr_.is_infinite(a) || tr_.is_infinite(b) || tr_.is_infinite(d)) continue;
      mesh.triangles.push_back({index_of(a), index_of(b), index_of(d)});
      mesh.triangle_patch.push_back(patch);
    }
  }
  // Consistent orientation across shared edges (closed pieces outward); a
  // non-manifold or non-orientable result keeps the triangles as they are.
  TriangleSoup soup{mesh.vertices, mesh.triangles};
  if (try_orient_triangle_mesh(soup, /*require_closed=*/false).ok()) {
    mesh.triangles = std::move(soup.triangles);
  }
}

void Refiner::extract_features(TetMesh& mesh) {
  // Feature vertices are found by position, not by handle: sliver exudation
  // re-inserts vertices with weights, which changes their handles but never
  // their positions.
  // Only the corners and the curve samples are looked up: a map of their
  // positions, filled by one pass over the vertices (not a map of every
  // vertex: some 70 bytes per vertex, at the run's peak).
  struct PointHash {
    std::size_t operator()(const Point3& p) const {
      const std::hash<double> h;
      return h(p.x) ^ (h(p.y) * 0x9e3779b97f4a7c15ULL) ^ (h(p.z) * 0xc2b2ae3d27d4eb4fULL);
    }
  };
  std::unordered_map<Point3, int, PointHash> index_at;
  for (const CornerInfo& corner : curves_.corners()) index_at.emplace(corner.point, -1);
  for (const CurveState& c : curves_.curves()) {
    for (const auto& sample : c.samples) index_at.emplace(sample.second.position, -1);
  }
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const auto it = index_at.find(mesh.vertices[i]);
    if (it != index_at.end() && it->second < 0) it->second = static_cast<int>(i);
  }
  auto index_of = [&](const Point3& p) {
    const auto it = index_at.find(p);
    return it == index_at.end() ? -1 : it->second;
  };
  mesh.curves = oracle_.curves();
  const std::vector<CornerInfo>& corners = curves_.corners();
  mesh.corners = corners;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const int index = index_of(corners[i].point);
    if (index < 0) continue;  // in no tetrahedron: the report shows the corner missing
    mesh.corner_vertices.push_back(index);
    mesh.corner_ids.push_back(CornerId{static_cast<int>(i) + 1});
  }
  for (const CurveState& c : curves_.curves()) {
    for (auto a = c.samples.begin(); std::next(a) != c.samples.end(); ++a) {
      const int i0 = index_of(a->second.position);
      const int i1 = index_of(std::next(a)->second.position);
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
