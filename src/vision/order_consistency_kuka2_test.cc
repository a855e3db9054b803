// Real images (data/rwhe-kuka2, see testing/kuka2_views.h): the first and the last of
// the 28 views, in CI (all 28: order_consistency_kuka2_slow_test).
#include <gtest/gtest.h>

#include "testing/kuka2_views.h"

namespace hecal::vision {
namespace {

// Real images (data/rwhe-kuka2): the first and the last of the 28 views. Both found with the
// order fixed by the pattern, and the ids are those of the same physical corners: the board's
// pose in the robot base frame (T_base_gripper · X · T_camera_target, X from SOURCE.md) is the
// same from both views, which a half turn of either would move by the board's diagonal (0.4 m).
TEST(Kuka2, FirstAndLastViewsGetTheSameCorners) {
  const kuka2::Views views = kuka2::Load({1, 28});
  ASSERT_EQ(views.detections.size(), 2u);
  for (const Detection& detection : views.detections) {
    ASSERT_EQ(detection.status, DetectionStatus::kFound) << detection.message;
    EXPECT_EQ(detection.order, PointOrder::kPattern);
  }
  const Pose a = kuka2::BaseTarget(views, 0), b = kuka2::BaseTarget(views, 1);
  EXPECT_LT((a.translation() - b.translation()).norm(), 0.003);
  EXPECT_LT(hecal::testing::RotationErrorDeg(a, b), 0.3);
}

}  // namespace
}  // namespace hecal::vision
