// A custom oracle through the C++ API: a ball answered in closed form.
//
// Any geometry can be meshed by implementing rdmesh::DomainOracle: a bounding
// box, point location, segment/surface intersection, a few points per patch,
// and projection (used only to measure the output's distance to the surface).
//
//   custom_oracle OUTPUT.mesh       meshes the ball and checks its volume
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include "rdmesh/errors.h"
#include "rdmesh/mesh_writers.h"
#include "rdmesh/mesher.h"
#include "rdmesh/oracle.h"
#include "rdmesh/quality_report.h"

namespace {

using namespace rdmesh;

class BallOracle final : public DomainOracle {
 public:
  BallOracle(Point3 center, double radius) : c_(center), r_(radius) {}

  Box3 bounding_box() const override {
    const Point3 m{1.1 * r_, 1.1 * r_, 1.1 * r_};
    return {c_ - m, c_ + m};
  }
  Located locate(const Point3& p, const std::optional<LocateHint>& = {}) const override {
    return {squared_norm(p - c_) < r_ * r_ ? SubdomainId{1} : kOutside};
  }
  std::optional<SurfaceHit> intersect(const Point3& a, const Point3& b) const override {
    if (locate(a).label == locate(b).label) return std::nullopt;
    // |a + t (b - a) - c|^2 = r^2, the root in [0, 1] (exactly one: labels differ).
    const Point3 d = b - a, m = a - c_;
    const double qa = dot(d, d), qb = 2 * dot(m, d), qc = dot(m, m) - r_ * r_;
    const double sq = std::sqrt(std::max(0.0, qb * qb - 4 * qa * qc));
    double t = (-qb - sq) / (2 * qa);
    if (t < 0 || t > 1) t = (-qb + sq) / (2 * qa);
    return SurfaceHit{a + std::clamp(t, 0.0, 1.0) * d, PatchId{1}};
  }
  std::vector<SubdomainInfo> subdomains() const override { return {{SubdomainId{1}, "ball"}}; }
  std::vector<PatchInfo> patches() const override {
    return {{PatchId{1}, "sphere", kOutside, SubdomainId{1}}};
  }
  std::vector<Point3> initial_points(PatchId) const override {
    std::vector<Point3> points;  // 8 points at the corners of an inscribed cube
    for (int i = 0; i < 8; ++i) {
      const Point3 dir{i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0};
      points.push_back(c_ + (r_ / std::sqrt(3.0)) * dir);
    }
    return points;
  }
  std::optional<Point3> project(const Point3& p, PatchId) const override {
    const double n = distance(p, c_);
    if (n == 0) return std::nullopt;
    return c_ + (r_ / n) * (p - c_);
  }
  /// Optional, for sizes by curvature (--curvature): a sphere's is 1 / r everywhere.
  std::optional<double> curvature(const Point3&, PatchId) const override { return 1 / r_; }
  double tolerance() const override { return 1e-12 * r_; }
  // A sphere has no sharp features.
  std::vector<CornerInfo> corners() const override { return {}; }
  std::vector<CurveInfo> curves() const override { return {}; }
  const Curve& curve(CurveId) const override { throw OracleError("the ball has no curves"); }

 private:
  Point3 c_;
  double r_;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: custom_oracle OUTPUT.mesh\n");
    return 2;
  }
  try {
    const BallOracle ball({0.5, 0, 0}, 2.0);
    Criteria criteria = default_criteria(ball.bounding_box());
    criteria.facet_size = criteria.cell_size = ScalarField::uniform(0.25);
    criteria.facet_distance = 0.01;
    const MeshResult result = generate_mesh(ball, criteria);
    write_mesh(result.mesh, argv[1]);
    const QualityReport report = measure_quality(result.mesh, &ball);
    const double exact = 4.0 / 3.0 * M_PI * 8.0;
    const double error = std::abs(report.subdomains.at(0).volume - exact) / exact;
    std::printf("%zu tets, volume error %.3f%%, boundary Euler characteristic %d\n",
                result.mesh.tets.size(), 100 * error, report.boundary_euler_characteristic);
    return error < 0.01 && report.boundary_euler_characteristic == 2 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "custom_oracle: error: %s\n", e.what());
    return 1;
  }
}
