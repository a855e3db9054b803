// CheckIntrinsicsFit on real images: data/rwhe-kuka2 (6 of its 1920 × 1200 chessboard images,
// SOURCE.md's reference intrinsics) and moveit_calibration's two photos with the intrinsics of
// its tests (data/moveit-calibration/SOURCE.md). The reference intrinsics fit; the mistakes of
// intrinsics_fit.h are refused with the correction that recovers the reference; and the layout
// moveit's ArUco test declares (4 × 3 markers; the print is 3 × 4) is blamed on the points.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "hecal/vision/intrinsics_fit.h"
#include "testing/kuka2_views.h"
#include "testing/moveit_photos.h"

namespace hecal::vision {
namespace {

using Kind = IntrinsicsCorrection::Kind;

std::vector<CalibrationView> ViewsOf(const std::vector<Detection>& detections,
                                     const pose::TargetSpec& target) {
  const std::vector<pose::ObjectPoint> board = pose::ObjectPoints(target);
  std::vector<CalibrationView> views;
  for (const Detection& detection : detections) {
    if (!detection.usable()) continue;
    CalibrationView view;
    for (const ImagePoint& p : detection.points) {
      view.object_points.push_back(board[static_cast<size_t>(p.id)].position);
      view.image_points.push_back(p.pixel);
    }
    views.push_back(view);
  }
  return views;
}

cv::Mat MoveItPhoto(const std::string& name) {
  return cv::imread(hecal::testing::MoveItPhotoPath(name), cv::IMREAD_GRAYSCALE);
}

// Measured (E / H px): reference 0.076 / 0.077; fx, fy 10× 23.5 / 1.65; cx, cy swapped
// 14.5 / 2.4 (intrinsics_fit.h, on 12 images; these 6 give the same verdicts).
TEST(IntrinsicsFitRealData, Kuka2ReferenceFitsAndMistakesAreNamed) {
  const kuka2::Views loaded = kuka2::Load({1, 5, 10, 15, 20, 25});
  const std::vector<CalibrationView> views = ViewsOf(loaded.detections, kuka2::Target());
  ASSERT_EQ(views.size(), 6u);
  const pose::CameraModel reference = kuka2::Camera();
  const IntrinsicsFit fit = CheckIntrinsicsFit(views, reference);
  EXPECT_EQ(fit.verdict, IntrinsicsVerdict::kFits);
  EXPECT_LT(fit.median_rms_px, 0.12);

  pose::CameraModel focal = reference;
  focal.fx *= 10.0;
  focal.fy *= 10.0;
  IntrinsicsFit wrong = CheckIntrinsicsFit(views, focal);
  EXPECT_EQ(wrong.verdict, IntrinsicsVerdict::kDoesNotFit);
  EXPECT_GT(wrong.median_rms_px, 10.0);
  ASSERT_TRUE(wrong.correction.has_value());
  EXPECT_EQ(wrong.correction->kind, Kind::kScaleFocal);
  EXPECT_NEAR(wrong.correction->camera.fx, reference.fx, 1.0);

  pose::CameraModel swapped = reference;
  std::swap(swapped.cx, swapped.cy);
  wrong = CheckIntrinsicsFit(views, swapped);
  EXPECT_EQ(wrong.verdict, IntrinsicsVerdict::kDoesNotFit);
  ASSERT_TRUE(wrong.correction.has_value());
  EXPECT_EQ(wrong.correction->kind, Kind::kSwapPrincipalPoint);
}

// Measured: ChArUco photo 0.25 / 0.20 px; ArUco photo declared 4 × 3: 41.9 / 41.8 px, as the
// print (3 × 4): 0.55 px.
TEST(IntrinsicsFitRealData, MoveItPhotos) {
  const pose::TargetSpec charuco = hecal::testing::MoveItCharucoBoard();
  const pose::CameraModel charuco_camera = hecal::testing::MoveItCharucoCamera();
  const IntrinsicsFit fit = CheckIntrinsicsFit(
      ViewsOf({DetectTarget(MoveItPhoto("test_charuco_board_detection.jpg"), charuco)}, charuco),
      charuco_camera);
  EXPECT_EQ(fit.verdict, IntrinsicsVerdict::kFits);

  const pose::TargetSpec declared = hecal::testing::MoveItArucoGrid();
  const pose::CameraModel aruco_camera = hecal::testing::MoveItArucoCamera();
  const cv::Mat photo = MoveItPhoto("test_aruco_marker_detection.png");
  const IntrinsicsFit layout =
      CheckIntrinsicsFit(ViewsOf({DetectTarget(photo, declared)}, declared), aruco_camera);
  EXPECT_EQ(layout.verdict, IntrinsicsVerdict::kDoesNotFit);
  EXPECT_TRUE(layout.points_do_not_fit);
  EXPECT_FALSE(layout.correction.has_value());
  pose::TargetSpec printed = declared;
  std::swap(printed.cols, printed.rows);
  const IntrinsicsFit right =
      CheckIntrinsicsFit(ViewsOf({DetectTarget(photo, printed)}, printed), aruco_camera);
  EXPECT_LT(right.median_rms_px, 1.0);
  EXPECT_NE(right.verdict, IntrinsicsVerdict::kDoesNotFit);
}

}  // namespace
}  // namespace hecal::vision
