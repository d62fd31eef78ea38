// The CGAL side of the sharp-features benchmark: Labeled_mesh_domain_3 with
// polyline features, so that Mesh_3 protects the curves with weighted balls.
#include "cgal_features_anchor.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_domain_with_polyline_features_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/make_mesh_3.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace rdmesh_bench {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Implicit_domain = CGAL::Labeled_mesh_domain_3<K>;
using Mesh_domain = CGAL::Mesh_domain_with_polyline_features_3<Implicit_domain>;
using Tr = CGAL::Mesh_triangulation_3<Mesh_domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, Mesh_domain::Corner_index,
                                                     Mesh_domain::Curve_index>;
using Mesh_criteria = CGAL::Mesh_criteria_3<Tr>;
using Polyline = std::vector<Point>;

double capped_cylinder(const Point& p) {
  return std::max(p.x() * p.x() + p.y() * p.y() - 0.25, std::abs(p.z()) - 0.6);
}

double cube(const Point& p) {
  return std::max({std::abs(p.x()), std::abs(p.y()), std::abs(p.z())}) - 0.5;
}

/// Closed circles of radius 0.5 at z = +-0.6, finely sampled (the polyline is
/// CGAL's curve: it must follow the circle far closer than the facet distance).
std::vector<Polyline> rims() {
  std::vector<Polyline> out;
  for (double z : {0.6, -0.6}) {
    Polyline line;
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
      const double t = 2 * M_PI * i / n;
      line.emplace_back(0.5 * std::cos(t), 0.5 * std::sin(t), z);
    }
    line.push_back(line.front());
    out.push_back(line);
  }
  return out;
}

std::vector<Polyline> cube_edges() {
  std::vector<Polyline> out;
  for (int axis = 0; axis < 3; ++axis) {
    for (double a : {-0.5, 0.5}) {
      for (double b : {-0.5, 0.5}) {
        double p[3], q[3];
        p[axis] = -0.5, q[axis] = 0.5;
        p[(axis + 1) % 3] = q[(axis + 1) % 3] = a;
        p[(axis + 2) % 3] = q[(axis + 2) % 3] = b;
        out.push_back({Point(p[0], p[1], p[2]), Point(q[0], q[1], q[2])});
      }
    }
  }
  return out;
}

}  // namespace

FeatureAnchorResult run_cgal_features(const std::string& shape, double h, bool optimize) {
  namespace params = CGAL::parameters;
  CGAL::Random rng(0);
  const bool cyl = shape == "capped_cylinder";
  if (!cyl && shape != "cube") throw std::invalid_argument("unknown feature shape: " + shape);
  // The same boxes as the rdmesh samples (samples/capped_cylinder.json, samples/cube.json).
  const CGAL::Bbox_3 box = cyl ? CGAL::Bbox_3(-0.8, -0.8, -0.9, 0.8, 0.8, 0.9)
                               : CGAL::Bbox_3(-0.7, -0.7, -0.7, 0.7, 0.7, 0.7);
  Mesh_domain domain(Implicit_domain::create_implicit_mesh_domain(
      cyl ? std::function<double(const Point&)>(capped_cylinder)
          : std::function<double(const Point&)>(cube),
      box, params::relative_error_bound = 1e-6, params::p_rng = &rng));
  const std::vector<Polyline> lines = cyl ? rims() : cube_edges();
  domain.add_features(lines.begin(), lines.end());
  Mesh_criteria criteria(params::edge_size = h, params::facet_angle = 25.0, params::facet_size = h,
                         params::facet_distance = h / 10, params::cell_radius_edge_ratio = 3.0,
                         params::cell_size = h);
  const auto t0 = std::chrono::steady_clock::now();
  C3t3 c3t3 =
      optimize
          ? CGAL::make_mesh_3<C3t3>(domain, criteria, params::perturb(), params::exude())
          : CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  FeatureAnchorResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::vector<Vec3> vertices;
  std::vector<Tet> tets;
  std::unordered_map<Tr::Vertex_handle, int> index;
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    Tet t{};
    for (int i = 0; i < 4; ++i) {
      const auto [it, inserted] = index.emplace(c->vertex(i), static_cast<int>(vertices.size()));
      if (inserted) {
        const auto& p = c->vertex(i)->point().point();
        vertices.push_back({p.x(), p.y(), p.z()});
      }
      t[i] = it->second;
    }
    tets.push_back(t);
  }
  r.vertices = vertices.size();
  r.quality = mesh_quality(vertices, tets);
  return r;
}

}  // namespace rdmesh_bench
