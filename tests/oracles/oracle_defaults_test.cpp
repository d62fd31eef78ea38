// DomainOracle's defaults: what a smooth custom oracle may leave out (the
// feature queries, intersect, the hint of locate) still meets the interface.
#include <gtest/gtest.h>

#include <string>

#include "oracles/oracle_conformance.h"
#include "rdmesh/errors.h"
#include "rdmesh/oracle.h"

namespace rdmesh {
namespace {

/// A ball of radius 1 at c, with only the queries the interface requires.
/// `layered` adds a second subdomain, the core |p - c| < 0.5, and its patch.
class MinimalBall final : public DomainOracle {
 public:
  explicit MinimalBall(bool layered = false) : layered_(layered) {}
  Box3 bounding_box() const override { return {c_ - Point3{2, 2, 2}, c_ + Point3{2, 2, 2}}; }
  Located locate(const Point3& p, const std::optional<LocateHint>& = std::nullopt) const override {
    const double d2 = squared_norm(p - c_);
    if (layered_ && d2 < 0.25) return {SubdomainId(2)};
    return {d2 < 1 ? SubdomainId(1) : kOutside};
  }
  std::vector<SubdomainInfo> subdomains() const override {
    if (!layered_) return {{SubdomainId(1), "ball"}};
    return {{SubdomainId(1), "shell"}, {SubdomainId(2), "core"}};
  }
  std::vector<PatchInfo> patches() const override {
    std::vector<PatchInfo> out = {{PatchId(1), "sphere", kOutside, SubdomainId(1)}};
    if (layered_) out.push_back({PatchId(2), "inner", SubdomainId(1), SubdomainId(2)});
    return out;
  }
  std::vector<Point3> initial_points(PatchId patch) const override {
    const double r = radius(patch);
    return {c_ + Point3{r, 0, 0}, c_ - Point3{r, 0, 0}, c_ + Point3{0, r, 0},
            c_ - Point3{0, r, 0}, c_ + Point3{0, 0, r}, c_ - Point3{0, 0, r}};
  }
  std::optional<Point3> project(const Point3& p, PatchId patch) const override {
    const double n = distance(p, c_);
    if (n == 0) return std::nullopt;
    return c_ + (radius(patch) / n) * (p - c_);
  }
  double tolerance() const override { return 1e-12; }

 private:
  static double radius(PatchId patch) { return patch.value == 2 ? 0.5 : 1.0; }
  Point3 c_{0.25, -0.5, 0.125};
  bool layered_;
};

/// A ball whose patches() forgets its sphere: an oracle breaking its contract.
class BallWithoutPatches final : public DomainOracle {
 public:
  Box3 bounding_box() const override { return {{-2, -2, -2}, {2, 2, 2}}; }
  Located locate(const Point3& p, const std::optional<LocateHint>& = std::nullopt) const override {
    return {squared_norm(p) < 1 ? SubdomainId(1) : kOutside};
  }
  std::vector<SubdomainInfo> subdomains() const override { return {{SubdomainId(1), "ball"}}; }
  std::vector<PatchInfo> patches() const override { return {}; }
  std::vector<Point3> initial_points(PatchId) const override { return {}; }
  std::optional<Point3> project(const Point3&, PatchId) const override { return std::nullopt; }
  double tolerance() const override { return 1e-12; }
};

TEST(OracleDefaults, ASmoothOracleHasNoFeaturesAndRefusesEveryCurve) {
  const MinimalBall o;
  EXPECT_TRUE(o.corners().empty());
  EXPECT_TRUE(o.curves().empty());
  for (int id : {0, 1}) {
    try {
      o.curve(CurveId(id));
      ADD_FAILURE() << "curve(" << id << ") returned";
    } catch (const OracleError& e) {
      EXPECT_EQ(std::string(e.what()), "no curve " + std::to_string(id) + " (there are none)");
    }
  }
}

// The default intersect (bisection on locate) meets intersect()'s guarantee:
// the shared suite checks every hit against the labels around it.
TEST(OracleDefaults, BisectionIntersectPassesTheConformanceSuite) {
  expect_oracle_conformance(MinimalBall());
  expect_oracle_conformance(MinimalBall(true));
}

TEST(OracleDefaults, BisectionIntersectIsOnTheSphereAndNamesThePatchBetweenItsLabels) {
  const MinimalBall o(true);
  const Point3 c{0.25, -0.5, 0.125};
  // One label change on each segment: core to shell across the inner sphere
  // (patch 2), shell to outside across the outer one (patch 1).
  const std::optional<SurfaceHit> inner = o.intersect(c, c + Point3{0.75, 0, 0});
  ASSERT_TRUE(inner);
  EXPECT_EQ(inner->patch, PatchId(2));
  EXPECT_NEAR(distance(inner->point, c), 0.5, 1e-12);
  const std::optional<SurfaceHit> outer =
      o.intersect(c + Point3{0, 0.75, 0}, c + Point3{0, 1.5, 0});
  ASSERT_TRUE(outer);
  EXPECT_EQ(outer->patch, PatchId(1));
  EXPECT_NEAR(distance(outer->point, c), 1.0, 1e-12);
  EXPECT_FALSE(o.intersect(c + Point3{0.6, 0, 0}, c + Point3{0, 0.6, 0}));  // both in the shell
}

TEST(OracleDefaults, BisectionIntersectRefusesLabelsNoPatchSeparates) {
  EXPECT_THROW(BallWithoutPatches().intersect({0, 0, 0}, {1.5, 0, 0}), OracleError);
}

}  // namespace
}  // namespace rdmesh
