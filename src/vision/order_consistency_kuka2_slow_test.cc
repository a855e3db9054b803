// All 28 real views of data/rwhe-kuka2 (24 × 17 inner corners, 15 mm squares; SOURCE.md: the
// first corner findChessboardCornersSB reports is at the board's lower right in every image).
// Every view is found with its order fixed by the pattern (24 + 17 is odd: the square colours
// tell the two ends apart), the canonical first corner sits at the same end of the board in
// every image, and the board's pose in the robot base frame (T_base_gripper · X · T_camera_target
// with SOURCE.md's reference X) agrees across all views — a half turn of any one view would move
// it by the board's diagonal (0.4 m) and turn it by 180°. Slow: ~2–6 s per image.
#include <gtest/gtest.h>

#include "testing/kuka2_views.h"

namespace hecal::vision {
namespace {

TEST(Kuka2, AllViewsFoundInOneConsistentOrder) {
  std::vector<int> numbers;
  for (int k = 1; k <= 28; ++k) numbers.push_back(k);
  const kuka2::Views views = kuka2::Load(numbers);
  ASSERT_EQ(views.detections.size(), 28u);
  int first_end = 0;
  for (size_t k = 0; k < views.detections.size(); ++k) {
    const Detection& detection = views.detections[k];
    ASSERT_EQ(detection.status, DetectionStatus::kFound)
        << "im_" << views.numbers[k] << ": " << detection.message;
    EXPECT_EQ(detection.order, PointOrder::kPattern);
    EXPECT_EQ(detection.num_points(), 24 * 17);
    // Which end of the board's diagonal id 0 is at, in the image (u + v larger or smaller).
    const Eigen::Vector2d diagonal = detection.points.front().pixel - detection.points.back().pixel;
    const int end = diagonal.sum() > 0.0 ? 1 : -1;
    if (k == 0) first_end = end;
    EXPECT_EQ(end, first_end) << "im_" << views.numbers[k];
  }
  const Pose reference = kuka2::BaseTarget(views, 0);
  double worst_translation = 0.0, worst_rotation = 0.0;
  for (size_t k = 1; k < views.detections.size(); ++k) {
    const Pose T = kuka2::BaseTarget(views, k);
    const double translation = (T.translation() - reference.translation()).norm();
    const double rotation = hecal::testing::RotationErrorDeg(T, reference);
    EXPECT_LT(translation, 0.003) << "im_" << views.numbers[k];
    EXPECT_LT(rotation, 0.3) << "im_" << views.numbers[k];
    worst_translation = std::max(worst_translation, translation);
    worst_rotation = std::max(worst_rotation, rotation);
  }
  std::cout << "board origin in the base frame: within " << worst_translation * 1e3 << " mm and "
            << worst_rotation << " deg of view 1's; id 0 at the "
            << (first_end > 0 ? "lower right" : "upper left") << " end in every image\n";
}

}  // namespace
}  // namespace hecal::vision
