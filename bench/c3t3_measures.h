// Shared by the CGAL anchors (cgal_anchor.cpp, polyhedral_anchor.cpp): the
// quality of a Mesh_3 complex through the shared helper, and the optimizers
// make_mesh_3(perturb(), exude()) runs after refinement, timed one by one.
// Header-only templates: only the anchors' translation units include Mesh_3.
#pragma once

#include <CGAL/exude_mesh_3.h>
#include <CGAL/perturb_mesh_3.h>

#include <chrono>
#include <unordered_map>
#include <vector>

#include "cgal_anchor.h"
#include "tet_quality.h"

namespace rdmesh_bench {

/// Cells in the complex as plain arrays, for the shared quality helper.
template <class C3t3>
MeshQuality complex_quality(const C3t3& c3t3, std::size_t* vertex_count = nullptr) {
  using Vertex_handle = typename C3t3::Triangulation::Vertex_handle;
  std::vector<Vec3> vertices;
  std::vector<Tet> tets;
  std::unordered_map<Vertex_handle, int> index;
  tets.reserve(c3t3.number_of_cells_in_complex());
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    Tet t{};
    for (int i = 0; i < 4; ++i) {
      const Vertex_handle v = c->vertex(i);
      auto [it, inserted] = index.emplace(v, static_cast<int>(vertices.size()));
      if (inserted) {
        const auto& p = v->point().point();  // weighted point -> bare point
        vertices.push_back({p.x(), p.y(), p.z()});
      }
      t[i] = it->second;
    }
    tets.push_back(t);
  }
  if (vertex_count != nullptr) *vertex_count = vertices.size();
  return mesh_quality(vertices, tets);
}

/// r.refine_seconds set: records the quality before, runs perturb_mesh_3 then
/// exude_mesh_3 as make_mesh_3(perturb(), exude()) does (default bounds, each
/// step's time limit = the refinement time) and times them.
template <class C3t3, class Domain>
void perturb_and_exude(C3t3& c3t3, const Domain& domain, AnchorResult& r) {
  namespace params = CGAL::parameters;
  const MeshQuality before = complex_quality(c3t3);
  r.min_dihedral_before_deg = before.min_dihedral_deg;
  r.below_10_deg_before = before.below_10_deg;
  auto seconds = [](std::chrono::steady_clock::time_point a,
                    std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  const auto t0 = std::chrono::steady_clock::now();
  CGAL::perturb_mesh_3(c3t3, domain, params::time_limit = r.refine_seconds);
  const auto t1 = std::chrono::steady_clock::now();
  r.min_dihedral_perturbed_deg = complex_quality(c3t3).min_dihedral_deg;
  const auto t2 = std::chrono::steady_clock::now();
  CGAL::exude_mesh_3(c3t3, params::time_limit = r.refine_seconds);
  const auto t3 = std::chrono::steady_clock::now();
  r.perturb_seconds = seconds(t0, t1);
  r.exude_seconds = seconds(t2, t3);
  r.seconds = r.refine_seconds + r.perturb_seconds + r.exude_seconds;
}

/// Fills the output measures of r from the final complex.
template <class C3t3>
void measure_complex(const C3t3& c3t3, bool optimized, AnchorResult& r) {
  std::size_t vertex_count = 0;
  const MeshQuality q = complex_quality(c3t3, &vertex_count);
  r.tets = q.tets;
  r.vertices = vertex_count;
  r.min_dihedral_deg = q.min_dihedral_deg;
  r.max_radius_edge = q.max_radius_edge;
  r.volume = q.volume;
  r.non_positive = q.non_positive;
  r.below_10_deg = q.below_10_deg;
  if (!optimized) {
    r.min_dihedral_before_deg = q.min_dihedral_deg;
    r.below_10_deg_before = q.below_10_deg;
  }
}

}  // namespace rdmesh_bench
