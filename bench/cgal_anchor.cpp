// CGAL Mesh_3 anchor: make_mesh_3 on the implicit benchmark domains. The only
// translation unit of rdmesh that instantiates Mesh_3 (compiles slowly).
#include "cgal_anchor.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/version_macros.h>

#include <chrono>
#include <stdexcept>

#include "c3t3_measures.h"
#include "shapes.h"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh_domain = CGAL::Labeled_mesh_domain_3<K>;
// Sequential on purpose: rdmesh refines sequentially, and the machine is shared.
using Tr = CGAL::Mesh_triangulation_3<Mesh_domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Mesh_criteria = CGAL::Mesh_criteria_3<Tr>;

double seconds_between(std::chrono::steady_clock::time_point a,
                       std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

AnchorResult run_cgal_anchor(const std::string& shape_name, double h, double relative_error_bound,
                             bool optimize) {
  const rdmesh_bench::Shape* shape = rdmesh_bench::find_shape(shape_name);
  if (shape == nullptr) throw std::invalid_argument("unknown shape: " + shape_name);
  const auto f = shape->f;
  const rdmesh_bench::BenchCriteria bc = rdmesh_bench::bench_criteria(h);

  namespace params = CGAL::parameters;
  // Fixed seed: the default CGAL::Random is seeded from the clock, which would
  // make the initial surface points (and the mesh) differ between runs.
  CGAL::Random rng(0);
  // Same box as the rdmesh oracle. The relative error bound (default 1e-3:
  // intersections within 1e-3 / 2 of the box diagonal along the segment)
  // decides the accuracy of surface points; rdmesh's oracle is far tighter (1e-10).
  const CGAL::Bbox_3 box(shape->lo[0], shape->lo[1], shape->lo[2], shape->hi[0], shape->hi[1],
                         shape->hi[2]);
  Mesh_domain domain = Mesh_domain::create_implicit_mesh_domain(
      [f](const Point& p) { return f(p.x(), p.y(), p.z()); }, box,
      params::relative_error_bound = relative_error_bound, params::p_rng = &rng);

  Mesh_criteria criteria(
      params::facet_angle = bc.facet_angle_deg, params::facet_size = bc.facet_size,
      params::facet_distance = bc.facet_distance,
      params::cell_radius_edge_ratio = bc.cell_radius_edge, params::cell_size = bc.cell_size);

  const auto t0 = std::chrono::steady_clock::now();
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  const auto t1 = std::chrono::steady_clock::now();

  AnchorResult r;
  r.refine_seconds = seconds_between(t0, t1);
  r.seconds = r.refine_seconds;
  if (optimize) rdmesh_bench::perturb_and_exude(c3t3, domain, r);
  rdmesh_bench::measure_complex(c3t3, optimize, r);
  return r;
}

std::string cgal_anchor_version() { return CGAL_VERSION_STR; }
