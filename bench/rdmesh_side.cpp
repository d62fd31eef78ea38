// rdmesh side of the benchmark: ImplicitOracle + generate_mesh, through the public API only.
#include "rdmesh_side.h"

#include <chrono>
#include <stdexcept>
#include <vector>

#include "rdmesh/criteria.h"
#include "rdmesh/implicit_oracle.h"
#include "rdmesh/mesher.h"
#include "shapes.h"
#include "tet_quality.h"

RdmeshResult measure_rdmesh(const rdmesh::MeshResult& result, double seconds) {
  const rdmesh::TetMesh& mesh = result.mesh;
  std::vector<rdmesh_bench::Vec3> vertices;
  vertices.reserve(mesh.vertices.size());
  for (const rdmesh::Point3& p : mesh.vertices) vertices.push_back({p.x, p.y, p.z});
  const rdmesh_bench::MeshQuality q = rdmesh_bench::mesh_quality(vertices, mesh.tets);

  RdmeshResult r;
  r.tets = mesh.tets.size();
  r.vertices = mesh.vertices.size();
  r.seconds = seconds;
  r.min_dihedral_deg = q.min_dihedral_deg;
  r.max_radius_edge = q.max_radius_edge;
  r.volume = q.volume;
  r.non_positive = q.non_positive;
  r.guard_rejections = result.stats.guard_rejections;
  r.below_10_deg = q.below_10_deg;
  const rdmesh::ExudationStats& ex = result.exudation;
  r.min_dihedral_before_deg = ex.ran ? ex.min_dihedral_before_deg : q.min_dihedral_deg;
  r.below_10_deg_before = ex.ran ? ex.histogram_before[0] + ex.histogram_before[1] : q.below_10_deg;
  r.optimize_seconds = ex.seconds;
  r.refine_seconds = r.seconds - ex.seconds;
  return r;
}

RdmeshResult run_rdmesh(const std::string& shape_name, double h, bool optimize) {
  const rdmesh_bench::Shape* shape = rdmesh_bench::find_shape(shape_name);
  if (shape == nullptr) throw std::invalid_argument("unknown shape: " + shape_name);
  const auto f = shape->f;
  const rdmesh_bench::BenchCriteria bc = rdmesh_bench::bench_criteria(h);

  const rdmesh::Box3 box{{shape->lo[0], shape->lo[1], shape->lo[2]},
                         {shape->hi[0], shape->hi[1], shape->hi[2]}};
  std::vector<rdmesh::ImplicitOracle::Function> functions;
  functions.emplace_back([f](const rdmesh::Point3& p) { return f(p.x, p.y, p.z); });

  const auto t0 = std::chrono::steady_clock::now();
  const rdmesh::ImplicitOracle oracle(box, std::move(functions));
  const auto t1 = std::chrono::steady_clock::now();

  rdmesh::Criteria criteria;
  criteria.facet_angle_deg = bc.facet_angle_deg;
  criteria.facet_size = rdmesh::ScalarField::uniform(bc.facet_size);
  criteria.facet_distance = bc.facet_distance;
  criteria.cell_size = rdmesh::ScalarField::uniform(bc.cell_size);
  criteria.cell_radius_edge = bc.cell_radius_edge;

  const auto t2 = std::chrono::steady_clock::now();
  rdmesh::MeshOptions options;
  options.exudation.enabled = optimize;
  const rdmesh::MeshResult result = rdmesh::generate_mesh(oracle, criteria, options);
  const auto t3 = std::chrono::steady_clock::now();

  RdmeshResult r = measure_rdmesh(result, std::chrono::duration<double>(t3 - t2).count());
  r.setup_seconds = std::chrono::duration<double>(t1 - t0).count();
  return r;
}
