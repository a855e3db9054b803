// Test support (not installed): moveit_calibration's two photos in data/moveit-calibration
// (SOURCE.md) with the targets and intrinsics its own tests declare.
//  - test_charuco_board_detection.jpg: ChArUco 5 × 7 squares, DICT_5X5_250, square 0.1971 / 7 m,
//    marker 0.0176 m; the camera of moveit's ChArUco test (plumb_bob).
//  - test_aruco_marker_detection.png: an ArUco grid declared 4 × 3 markers (the print is 3 × 4),
//    DICT_4X4_250, marker 0.0256 m, gap 0.0066 m; the camera of moveit's ArUco test (no
//    distortion).
#pragma once

#include <array>
#include <string>

#include "hecal/pose/camera_model.h"
#include "hecal/pose/target.h"

namespace hecal::testing {

inline std::string MoveItPhotoPath(const std::string& name) {
  return std::string(HECAL_SOURCE_DIR) + "/data/moveit-calibration/" + name;
}

inline pose::CameraModel MoveItCamera(double fx, double fy, double cx, double cy,
                                      const std::array<double, 5>& distortion) {
  pose::CameraModel camera;
  camera.fx = fx;
  camera.fy = fy;
  camera.cx = cx;
  camera.cy = cy;
  camera.width = 640;
  camera.height = 480;
  camera.distortion = distortion;
  return camera;
}

inline pose::CameraModel MoveItCharucoCamera() {
  return MoveItCamera(590.6972346, 592.84676713, 322.33104773, 247.40030325,
                      {0.15405498, -0.24916842, 0.00350791, -0.00110041, 0.0});
}

inline pose::CameraModel MoveItArucoCamera() {
  return MoveItCamera(618.6002197265625, 619.1103515625, 321.9837646484375, 241.1459197998047,
                      {0.0, 0.0, 0.0, 0.0, 0.0});
}

inline pose::TargetSpec MoveItCharucoBoard() {
  pose::TargetSpec target;
  target.type = pose::TargetType::kCharuco;
  target.cols = 5;
  target.rows = 7;
  target.square = 0.1971 / 7.0;
  target.marker = 0.0176;
  target.dictionary = "DICT_5X5_250";
  return target;
}

// The layout moveit's test declares (4 × 3).
inline pose::TargetSpec MoveItArucoGrid() {
  pose::TargetSpec target;
  target.type = pose::TargetType::kArucoGrid;
  target.cols = 4;
  target.rows = 3;
  target.marker = 0.0256;
  target.spacing = 0.0066;
  target.dictionary = "DICT_4X4_250";
  return target;
}

}  // namespace hecal::testing
