// Tests of ImplicitOracle on analytic domains (C++ functions, no file).
#include "rdmesh/implicit_oracle.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <random>

#include "oracles/oracle_conformance.h"
#include "rdmesh/errors.h"

namespace rdmesh {
namespace {

double sphere(const Point3& p, Point3 c, double r) { return squared_norm(p - c) - r * r; }

Box3 cube(double h) { return {{-h, -h, -h}, {h, h, h}}; }

ImplicitOracle unit_sphere_oracle() {
  return ImplicitOracle(cube(1.2), {[](const Point3& p) { return sphere(p, {}, 1); }});
}

TEST(ImplicitOracle, SphereLabelsAndPatch) {
  const ImplicitOracle o = unit_sphere_oracle();
  EXPECT_EQ(o.locate({0, 0, 0}), SubdomainId(1));
  EXPECT_EQ(o.locate({0.9, 0, 0}), SubdomainId(1));
  EXPECT_EQ(o.locate({1.1, 0, 0}), kOutside);
  EXPECT_EQ(o.locate({5, 0, 0}), kOutside);
  ASSERT_EQ(o.subdomains().size(), 1u);
  ASSERT_EQ(o.patches().size(), 1u);
  const PatchInfo patch = o.patches()[0];
  EXPECT_EQ(patch.side_a, kOutside);
  EXPECT_EQ(patch.side_b, SubdomainId(1));
  EXPECT_EQ(patch.id, o.patch_between(kOutside, SubdomainId(1)));
  EXPECT_DOUBLE_EQ(o.tolerance(), 1e-10 * o.bounding_box().diagonal());
}

TEST(ImplicitOracle, SphereConformance) { expect_oracle_conformance(unit_sphere_oracle()); }

TEST(ImplicitOracle, IntersectionAccuracyOnTheExactSphere) {
  const ImplicitOracle o = unit_sphere_oracle();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Point3 a{0.5 * u(rng), 0.5 * u(rng), 0.5 * u(rng)};
    const Point3 b{1.2 * u(rng), 1.2 * u(rng), 1.2 * u(rng)};
    if (norm(b) <= 1) continue;
    const auto hit = o.intersect(a, b);
    ASSERT_TRUE(hit.has_value());
    EXPECT_LE(std::abs(norm(hit->point) - 1), 1e-9);
    ++hits;
  }
  EXPECT_GT(hits, 500);
  EXPECT_FALSE(o.intersect({0, 0, 0}, {0.5, 0.5, 0}).has_value());
}

TEST(ImplicitOracle, FewEvaluationsPerIntersection) {
  auto count = std::make_shared<std::atomic<long>>(0);
  const ImplicitOracle o(cube(1.2), {[count](const Point3& p) {
                           count->fetch_add(1, std::memory_order_relaxed);
                           return sphere(p, {0.1, -0.05, 0.02}, 1);
                         }});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  long calls = 0, evaluations = 0;
  for (int i = 0; i < 5000; ++i) {
    const Point3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)};
    if (o.locate(a) == o.locate(b)) continue;
    ++calls;
    const long before = count->load();
    ASSERT_TRUE(o.intersect(a, b).has_value());
    evaluations += count->load() - before;
  }
  const double per_call = static_cast<double>(evaluations) / static_cast<double>(calls);
  RecordProperty("evaluations_per_intersect", std::to_string(per_call));
  std::printf("evaluations per intersect: %.2f over %ld calls\n", per_call, calls);
  EXPECT_GT(calls, 500);
  EXPECT_LT(per_call, 20.0);
}

}  // namespace
}  // namespace rdmesh
