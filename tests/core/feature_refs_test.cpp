// The typed references core keeps to features: a vertex's FeatureRef
// (triangulation_types.h) and a protecting ball's BallRef (protection.h). Each
// id is read through the accessor of its kind; with RDMESH_DEBUG_CHECKS a read
// of the wrong kind is an InternalError instead of a wrong table index.
#include <gtest/gtest.h>

#include "protection.h"
#include "triangulation_types.h"

namespace rdmesh::detail {
namespace {

TEST(FeatureRef, KeepsTheDimensionAndTheIdOfItsFeature) {
  EXPECT_EQ(FeatureRef().dim(), FeatureDim::kVolume);
  EXPECT_EQ(FeatureRef(CornerId{4}).dim(), FeatureDim::kCorner);
  EXPECT_EQ(FeatureRef(CornerId{4}).corner(), CornerId{4});
  EXPECT_EQ(FeatureRef(CurveId{7}).curve(), CurveId{7});
  EXPECT_EQ(FeatureRef(PatchId{2}).patch(), PatchId{2});
  // No more bytes per vertex than the int and the dimension it replaced.
  EXPECT_LE(sizeof(FeatureRef), 2 * sizeof(int));
  EXPECT_EQ(sizeof(CellInfo::facet_patch), 4 * sizeof(int));
#if RDMESH_DEBUG_CHECKS
  EXPECT_THROW(FeatureRef(CurveId{7}).patch(), InternalError);
  EXPECT_THROW(FeatureRef(PatchId{2}).corner(), InternalError);
  EXPECT_THROW(FeatureRef().curve(), InternalError);
#endif
}

TEST(BallRef, NamesACornerOrACurveSampleAndComparesBallsNotFactors) {
  const BallRef corner = BallRef::at_corner(3);
  const BallRef sample = BallRef::on_curve(3, 5);
  EXPECT_TRUE(corner.is_corner());
  EXPECT_EQ(corner.corner(), 3);
  EXPECT_FALSE(sample.is_corner());
  EXPECT_EQ(sample.curve(), 3);
  EXPECT_EQ(sample.sample(), 5);
  // Corner 3 and curve 3's samples are different balls.
  EXPECT_FALSE(corner.same_ball(BallRef::on_curve(3, 0)));
  BallRef smaller = BallRef::on_curve(3, 5);
  smaller.factor = 0.1;
  EXPECT_TRUE(sample.same_ball(smaller));
  EXPECT_FALSE(sample.same_ball(BallRef::on_curve(3, 6)));
#if RDMESH_DEBUG_CHECKS
  EXPECT_THROW(corner.curve(), InternalError);
  EXPECT_THROW(sample.corner(), InternalError);
#endif
}

}  // namespace
}  // namespace rdmesh::detail
