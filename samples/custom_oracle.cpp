// A custom oracle through the C++ API: a ball. A smooth rdmesh::DomainOracle gives
// a box, point location, a few points per patch and projection (to measure the
// output); crossings default to bisection on locate(), sharp features to none.
//   custom_oracle OUTPUT.mesh       meshes the ball and checks its volume
#include <cmath>
#include <cstdio>
#include <exception>

#include "rdmesh/mesh_writers.h"
#include "rdmesh/mesher.h"
#include "rdmesh/quality_report.h"

using namespace rdmesh;

struct BallOracle final : DomainOracle {
  Point3 c{0.5, 0, 0};
  double r = 2;

  Box3 bounding_box() const override {
    return {c - 1.1 * Point3{r, r, r}, c + 1.1 * Point3{r, r, r}};
  }
  Located locate(const Point3& p, const std::optional<LocateHint>& = {}) const override {
    return {squared_norm(p - c) < r * r ? SubdomainId{1} : kOutside};
  }
  std::vector<SubdomainInfo> subdomains() const override { return {{SubdomainId{1}, "ball"}}; }
  std::vector<PatchInfo> patches() const override {
    return {{PatchId{1}, "sphere", kOutside, SubdomainId{1}}};
  }
  std::vector<Point3> initial_points(PatchId) const override {  // an inscribed octahedron
    return {c + Point3{r, 0, 0}, c - Point3{r, 0, 0}, c + Point3{0, r, 0},
            c - Point3{0, r, 0}, c + Point3{0, 0, r}, c - Point3{0, 0, r}};
  }
  std::optional<Point3> project(const Point3& p, PatchId) const override {
    const double n = distance(p, c);
    if (n == 0) return std::nullopt;
    return c + (r / n) * (p - c);
  }
  /// Optional, for sizes by curvature (--curvature): a sphere's is 1 / r everywhere.
  std::optional<double> curvature(const Point3&, PatchId) const override { return 1 / r; }
  double tolerance() const override { return 1e-12 * r; }
};

int main(int argc, char** argv) try {
  if (argc != 2) return std::fprintf(stderr, "usage: custom_oracle OUTPUT.mesh\n"), 2;
  const BallOracle ball;
  Criteria criteria = default_criteria(ball.bounding_box());
  criteria.facet_size = criteria.cell_size = ScalarField::uniform(0.25);
  criteria.facet_distance = 0.01;
  const MeshResult result = generate_mesh(ball, criteria);
  write_mesh(result.mesh, argv[1]);
  const QualityReport report = measure_quality(result.mesh, &ball);
  const double error = std::abs(report.subdomains.at(0).volume / (4 / 3.0 * M_PI * 8) - 1);
  std::printf("%zu tets, volume error %.3f%%, boundary Euler characteristic %d\n",
              result.mesh.tets.size(), 100 * error, report.boundary_euler_characteristic);
  return error < 0.01 && report.boundary_euler_characteristic == 2 ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "custom_oracle: error: %s\n", e.what());
  return 1;
}
