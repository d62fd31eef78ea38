// D|L's table of corners and curves (restricted_curves.h): the core indexes
// them by id - 1, so it refuses an oracle that does not number them 1..n in
// order. The built-in oracles number theirs with a FeatureTable, which cannot
// go wrong; a custom oracle keeping its own lists (as the capped cylinder
// fixture does) is checked only here.
#include "restricted_curves.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "capped_cylinder_oracle.h"
#include "rdmesh/errors.h"

namespace rdmesh::detail {
namespace {

/// The capped cylinder with its two rims listed in the wrong order (ids 2, 1).
class RimsOutOfOrder final : public DomainOracle {
 public:
  Box3 bounding_box() const override { return o.bounding_box(); }
  Located locate(const Point3& p,
                 const std::optional<LocateHint>& hint = std::nullopt) const override {
    return o.locate(p, hint);
  }
  std::optional<SurfaceHit> intersect(const Point3& a, const Point3& b) const override {
    return o.intersect(a, b);
  }
  std::vector<SubdomainInfo> subdomains() const override { return o.subdomains(); }
  std::vector<PatchInfo> patches() const override { return o.patches(); }
  std::vector<Point3> initial_points(PatchId patch) const override {
    return o.initial_points(patch);
  }
  std::optional<Point3> project(const Point3& p, PatchId patch) const override {
    return o.project(p, patch);
  }
  double tolerance() const override { return o.tolerance(); }
  std::vector<CurveInfo> curves() const override {
    std::vector<CurveInfo> c = o.curves();
    std::swap(c[0], c[1]);
    return c;
  }
  const Curve& curve(CurveId id) const override { return o.curve(id); }

  test::CappedCylinderOracle o{1.0, 1.0};
};

TEST(RestrictedCurves, TakesTheCurvesOfAnOracleNumberingThemInOrder) {
  const test::CappedCylinderOracle oracle(1.0, 1.0);
  const RestrictedCurves curves(oracle);
  ASSERT_EQ(curves.curves().size(), 2u);
  EXPECT_EQ(curves.curves()[0].info.name, "top rim");
  EXPECT_EQ(curves.curves()[1].info.id, CurveId{2});
}

TEST(RestrictedCurves, RefusesAnOracleWhoseCurveIdsAreNotOneToNInOrder) {
  const RimsOutOfOrder oracle;
  try {
    const RestrictedCurves curves(oracle);
    FAIL() << "curves listed as 2, 1 were accepted";
  } catch (const OracleError& e) {
    EXPECT_NE(std::string(e.what()).find("curves must have ids 1..n in order"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace rdmesh::detail
