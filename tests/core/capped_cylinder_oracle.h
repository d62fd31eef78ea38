// Test fixture: an analytic capped cylinder r < R, |z| < H with its three
// patches (side 1, top 2, bottom 3) and its two rim circles as curves. It
// exercises the core's feature handling independently of any oracle library.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>

#include "rdmesh/errors.h"
#include "rdmesh/oracle.h"
#include "rdmesh/parametric_curve.h"

namespace rdmesh::test {

class CappedCylinderOracle final : public DomainOracle {
 public:
  CappedCylinderOracle(double radius, double half_height) : r_(radius), h_(half_height) {
    for (double z : {h_, -h_}) {
      rims_.push_back(std::make_shared<ParametricCurve>(
          [this, z](double t) {
            return Point3{r_ * std::cos(t), r_ * std::sin(t), z};
          },
          0.0, 2 * M_PI));
    }
  }

  Box3 bounding_box() const override {
    const double m = 0.2 * std::max(r_, h_);
    return {{-r_ - m, -r_ - m, -h_ - m}, {r_ + m, r_ + m, h_ + m}};
  }
  Located locate(const Point3& p, const std::optional<LocateHint>& = std::nullopt) const override {
    return {p.x * p.x + p.y * p.y < r_ * r_ && std::abs(p.z) < h_ ? SubdomainId{1} : kOutside};
  }
  std::optional<SurfaceHit> intersect(const Point3& a, const Point3& b) const override {
    if (locate(a).label == locate(b).label) return std::nullopt;
    Point3 in = locate(a).label == kOutside ? b : a, out = locate(a).label == kOutside ? a : b;
    for (int i = 0; i < 200 && distance(in, out) > 1e-13; ++i) {
      const Point3 m = 0.5 * (in + out);
      (locate(m).label == kOutside ? out : in) = m;
    }
    const Point3 x = 0.5 * (in + out);
    return SurfaceHit{x, patch_at(x)};
  }
  std::vector<SubdomainInfo> subdomains() const override { return {{SubdomainId{1}, "cylinder"}}; }
  std::vector<PatchInfo> patches() const override {
    return {{PatchId{1}, "side", kOutside, SubdomainId{1}},
            {PatchId{2}, "top", kOutside, SubdomainId{1}},
            {PatchId{3}, "bottom", kOutside, SubdomainId{1}}};
  }
  std::vector<Point3> initial_points(PatchId patch) const override {
    std::vector<Point3> points;
    for (int k = 0; k < 6; ++k) {
      const double t = 2 * M_PI * (k + 0.5) / 6;
      if (patch.value == 1)
        points.push_back({r_ * std::cos(t), r_ * std::sin(t), (k % 3 - 1) * 0.5 * h_});
      if (patch.value > 1) {
        points.push_back(
            {0.5 * r_ * std::cos(t), 0.5 * r_ * std::sin(t), patch.value == 2 ? h_ : -h_});
      }
    }
    return points;
  }
  std::optional<Point3> project(const Point3& p, PatchId patch) const override {
    const double rho = std::hypot(p.x, p.y);
    if (patch.value == 1) {
      if (rho == 0) return std::nullopt;
      return Point3{r_ * p.x / rho, r_ * p.y / rho, std::clamp(p.z, -h_, h_)};
    }
    const double s = rho > r_ ? r_ / rho : 1.0;
    return Point3{s * p.x, s * p.y, patch.value == 2 ? h_ : -h_};
  }
  /// 1 / r on the side, 0 on the caps.
  std::optional<double> curvature(const Point3&, PatchId patch) const override {
    if (patch.value < 1 || patch.value > 3) return std::nullopt;
    return patch.value == 1 ? 1 / r_ : 0.0;
  }
  double tolerance() const override { return 1e-12; }
  std::vector<CornerInfo> corners() const override { return {}; }
  std::vector<CurveInfo> curves() const override {
    return {{CurveId{1},
             "top rim",
             true,
             0.0,
             2 * M_PI,
             CornerId{0},
             CornerId{0},
             {PatchId{1}, PatchId{2}}},
            {CurveId{2},
             "bottom rim",
             true,
             0.0,
             2 * M_PI,
             CornerId{0},
             CornerId{0},
             {PatchId{1}, PatchId{3}}}};
  }
  const Curve& curve(CurveId id) const override {
    if (id.value < 1 || id.value > 2) throw OracleError("no such curve");
    return *rims_[id.value - 1];
  }
  /// The patch a boundary point lies on: the constraint it is closest to saturating.
  PatchId patch_at(const Point3& x) const {
    const double side = std::abs(std::hypot(x.x, x.y) - r_);
    const double cap = std::abs(std::abs(x.z) - h_);
    if (side <= cap) return PatchId{1};
    return x.z > 0 ? PatchId{2} : PatchId{3};
  }

 private:
  double r_, h_;
  std::vector<std::shared_ptr<ParametricCurve>> rims_;
};

}  // namespace rdmesh::test
