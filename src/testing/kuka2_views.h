// Test support: the real eye-in-hand views of data/rwhe-kuka2 (Ali et al. 2019; SOURCE.md):
// 1920 × 1200 images of a 24 × 17 inner-corner chessboard with 15 mm squares, the robot poses
// (RobotPosesVec.txt: row-major 4 × 4 T_base_gripper, metres), the reference intrinsics and the
// reference X = T_gripper_camera computed by SOURCE.md's author with OpenCV.
#pragma once

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "hecal/geometry/so3.h"
#include "hecal/geometry/types.h"
#include "hecal/vision/detection.h"
#include "testing/detection_errors.h"
#include "testing/kuka2_scene.h"
#include "testing/rendered_scene.h"

namespace hecal::vision::kuka2 {

inline pose::TargetSpec Target() {
  return hecal::testing::Chessboard(24, 17, 0.015);
}

inline pose::CameraModel Camera() {
  return {1056.2855,
          1056.4172,
          958.7994,
          586.9487,
          1920,
          1200,
          {-0.131337, 0.099230, 0.000133, 0.000312, -0.049132}};
}

// SOURCE.md's reference X = T_gripper_camera (OpenCV PARK, confirmed by four other methods).
inline Pose X() {
  return MakePose(so3::Exp(Eigen::Vector3d(-1.20742, 1.28362, -1.18276)),
                  Eigen::Vector3d(0.01439, -0.10790, -0.08187));
}

struct Views {
  std::vector<int> numbers;           // image numbers, 1..28
  std::vector<Detection> detections;  // DetectTarget on each image
  std::vector<Pose> T_base_gripper;   // robot pose of each image
  std::vector<Pose> T_camera_target;  // cv::solvePnP on each detection (when usable)
};

inline std::string Directory() {
  return std::string(HECAL_SOURCE_DIR) + "/data/rwhe-kuka2/";
}

// Detects the board in images `numbers` (1-based) and reads their robot poses.
inline Views Load(const std::vector<int>& numbers) {
  const std::vector<Pose> robot = hecal::testing::kuka2::RobotPoses();
  Views views;
  for (const int number : numbers) {
    const std::string name =
        Directory() + "images/im_" + (number < 10 ? "0" : "") + std::to_string(number) + ".png";
    const cv::Mat image = cv::imread(name, cv::IMREAD_GRAYSCALE);
    if (image.empty() || number < 1 || number > static_cast<int>(robot.size())) {
      ADD_FAILURE() << "cannot read " << name << " or its robot pose";
      return {};
    }
    views.numbers.push_back(number);
    views.detections.push_back(DetectTarget(image, Target()));
    views.T_base_gripper.push_back(robot[static_cast<size_t>(number - 1)]);
    views.T_camera_target.push_back(
        views.detections.back().usable()
            ? hecal::testing::OpenCvPose(views.detections.back(), Target(), Camera())
            : Pose::Identity());
  }
  return views;
}

// The board's pose in the robot base frame seen from view k: T_base_gripper · X · T_camera_target.
inline Pose BaseTarget(const Views& views, size_t k) {
  return views.T_base_gripper[k] * X() * views.T_camera_target[k];
}

}  // namespace hecal::vision::kuka2
