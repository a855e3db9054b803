// Real images: the ChArUco and ArUco-grid photos of MoveIt Calibration's target tests
// (data/moveit-calibration/SOURCE.md, with their boards, intrinsics and expected board poses).
// Each is detected, its pose computed with cv::solvePnP (SOLVEPNP_ITERATIVE) and compared
//   - with the OpenCV 4.6 pose SOURCE.md reports (board frame of OpenCV 4.6 = hecal's target
//     frame): rotation and translation, within what the corner refinement may change, and
//   - after SOURCE.md's conversion to the legacy board frame (origin bottom-left, y up, z out of
//     the board: R_old = R · diag(1, −1, −1), t_old = t + H · R[:, 1], H the board height), with
//     the upstream test's own check: translation().isApprox(t, 0.01) and
//     rotation().eulerAngles(0, 1, 2).isApprox(r, 0.01).
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "hecal/vision/detection.h"
#include "testing/detection_errors.h"
#include "testing/moveit_photos.h"

namespace hecal::vision {
namespace {

using testing::MoveItPhotoPath;

// The pose in the legacy (pre-4.6) board frame, SOURCE.md's conversion.
Pose LegacyBoardFrame(const Pose& T, double board_height) {
  const Eigen::Matrix3d R_old = T.linear() * Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  return MakePose(R_old, T.translation() + board_height * T.linear().col(1));
}

struct Expected {
  Eigen::Vector3d rvec_opencv46, t_opencv46;   // SOURCE.md, OpenCV 4.6 board frame
  Eigen::Vector3d t_upstream, euler_upstream;  // moveit_calibration's test, legacy frame
};

void CheckPose(const Detection& detection, const pose::TargetSpec& target,
               const pose::CameraModel& camera, double board_height, const Expected& expected) {
  const Pose T = hecal::testing::OpenCvPose(detection, target, camera);
  const Pose T_opencv46 = MakePose(so3::Exp(expected.rvec_opencv46), expected.t_opencv46);
  const double rotation = hecal::testing::RotationErrorDeg(T, T_opencv46);
  const double translation = (T.translation() - T_opencv46.translation()).norm();
  std::cout << pose::TargetTypeName(target.type) << ": " << detection.message << "; vs OpenCV 4.6 "
            << rotation << " deg, " << translation * 1e3 << " mm\n";
  EXPECT_LT(rotation, 0.5);
  EXPECT_LT(translation, 0.003);

  const Pose legacy = LegacyBoardFrame(T, board_height);
  const Eigen::Vector3d euler = legacy.linear().eulerAngles(0, 1, 2);
  std::cout << "  legacy t " << legacy.translation().transpose() << " (upstream "
            << expected.t_upstream.transpose() << "), euler " << euler.transpose() << " (upstream "
            << expected.euler_upstream.transpose() << ")\n";
  EXPECT_TRUE(legacy.translation().isApprox(expected.t_upstream, 0.01));
  EXPECT_TRUE(euler.isApprox(expected.euler_upstream, 0.01));
}

// 5 × 7 squares, DICT_5X5_250, square 0.1971 / 7 m, marker 0.0176 m; SOURCE.md: 17 markers,
// 24 corners with OpenCV 4.6.
TEST(MoveItImages, CharucoBoardPose) {
  const pose::TargetSpec target = testing::MoveItCharucoBoard();
  const cv::Mat image =
      cv::imread(MoveItPhotoPath("test_charuco_board_detection.jpg"), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  const Detection detection = DetectTarget(image, target);
  ASSERT_EQ(detection.status, DetectionStatus::kFound) << detection.message;
  EXPECT_EQ(detection.num_points(), 24);
  const pose::CameraModel camera = testing::MoveItCharucoCamera();
  CheckPose(
      detection, target, camera, 7.0 * target.square,
      {Eigen::Vector3d(-0.31304, -0.01452, -1.14793),
       Eigen::Vector3d(-0.078898, 0.029991, 0.373471), Eigen::Vector3d(0.09752, 0.102848, 0.325596),
       Eigen::Vector3d(2.88409, -0.147996, 1.13757)});
}

// 4 × 3 markers, DICT_4X4_250, marker 0.0256 m, separation 0.0066 m, no distortion; SOURCE.md:
// all 12 markers with OpenCV 4.6.
TEST(MoveItImages, ArucoGridPose) {
  const pose::TargetSpec target = testing::MoveItArucoGrid();
  const cv::Mat image =
      cv::imread(MoveItPhotoPath("test_aruco_marker_detection.png"), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  const Detection detection = DetectTarget(image, target);
  ASSERT_EQ(detection.status, DetectionStatus::kFound) << detection.message;
  EXPECT_EQ(detection.num_points(), 48);
  const pose::CameraModel camera = testing::MoveItArucoCamera();
  CheckPose(detection, target, camera, 3.0 * target.marker + 2.0 * target.spacing,
            {Eigen::Vector3d(0.170675, 1.532646, 0.265517),
             Eigen::Vector3d(0.020612, -0.074049, 0.561406),
             Eigen::Vector3d(0.0148984, 0.0123107, 0.58609),
             Eigen::Vector3d(2.12328, -1.50481, -1.29729)});
}

}  // namespace
}  // namespace hecal::vision
