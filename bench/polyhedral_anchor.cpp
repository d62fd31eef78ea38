// Triangle-mesh benchmark sides (see polyhedral_anchor.h). Both read the file
// with rdmesh's reader (duplicates merged, oriented), so they mesh the same surface.
#include "polyhedral_anchor.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/make_mesh_3.h>

#include <chrono>
#include <cmath>
#include <cstdlib>

#include "c3t3_measures.h"
#include "rdmesh/mesher.h"
#include "rdmesh/triangle_mesh_check.h"
#include "rdmesh/triangle_mesh_oracle.h"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polyhedron = CGAL::Polyhedron_3<K, CGAL::Mesh_3::Mesh_polyhedron_items<int>>;
using Domain = CGAL::Polyhedral_mesh_domain_with_features_3<K, Polyhedron>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;

/// The file of a "mesh:FILE" shape: in $RDMESH_DATA_DIR/mesh, else the shared
/// data beside the checkout.
std::string path_of(const std::string& shape) {
  const char* env = std::getenv("RDMESH_DATA_DIR");
  const std::string dir = env != nullptr ? env : std::string(RDMESH_SOURCE_DIR) + "/../shared/data";
  return dir + "/mesh/" + shape.substr(5);
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

bool is_polyhedral_shape(const std::string& shape) { return shape.rfind("mesh:", 0) == 0; }

RdmeshResult run_rdmesh_polyhedral(const std::string& shape, double h_fraction, bool optimize) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto oracle = rdmesh::TriangleMeshOracle::from_file(path_of(shape));
  const double setup = seconds_since(t0);
  const double h = h_fraction * oracle->bounding_box().diagonal();
  rdmesh::Criteria criteria;
  criteria.edge_size = criteria.facet_size = criteria.cell_size = rdmesh::ScalarField::uniform(h);
  criteria.facet_distance = h / 10;
  rdmesh::MeshOptions options;
  options.exudation.enabled = optimize;
  const auto t1 = std::chrono::steady_clock::now();
  const rdmesh::MeshResult result = rdmesh::generate_mesh(*oracle, criteria, options);
  RdmeshResult r = measure_rdmesh(result, seconds_since(t1));
  r.setup_seconds = setup;
  return r;
}

AnchorResult run_cgal_polyhedral(const std::string& shape, double h_fraction, bool optimize) {
  rdmesh::TriangleSoup soup = rdmesh::read_triangle_mesh(path_of(shape));
  rdmesh::orient_triangle_mesh(soup, shape, true);
  std::vector<K::Point_3> points;
  for (const rdmesh::Point3& p : soup.points) points.emplace_back(p.x, p.y, p.z);
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& t : soup.triangles)
    polygons.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
  Polyhedron poly;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, poly);
  const auto box = CGAL::Polygon_mesh_processing::bbox(poly);
  const double diag =
      std::sqrt(std::pow(box.xmax() - box.xmin(), 2) + std::pow(box.ymax() - box.ymin(), 2) +
                std::pow(box.zmax() - box.zmin(), 2));
  const double h = h_fraction * diag * 1.02;  // rdmesh's box is 1% larger on each side
  namespace params = CGAL::parameters;
  const auto t0 = std::chrono::steady_clock::now();
  Domain domain(poly);
  domain.detect_features(60);
  const Criteria criteria(params::edge_size = h, params::facet_angle = 25, params::facet_size = h,
                          params::facet_distance = h / 10, params::cell_radius_edge_ratio = 2,
                          params::cell_size = h);
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  AnchorResult r;
  r.refine_seconds = seconds_since(t0);
  r.seconds = r.refine_seconds;
  if (optimize) rdmesh_bench::perturb_and_exude(c3t3, domain, r);
  rdmesh_bench::measure_complex(c3t3, optimize, r);
  return r;
}
