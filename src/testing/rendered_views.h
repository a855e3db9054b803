// Test support for the CLI tests on rendered images (detect_test, calibrate_images_test): a 9 × 6
// chessboard and a single AprilTag, a known camera, views of either from chosen directions, and
// their rendering (vision/render.h) into PNG files.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"
#include "hecal/pose/target.h"
#include "hecal/vision/render.h"
#include "testing/camera_yaml.h"
#include "testing/synthetic_views.h"

namespace hecal::cli::rendered_views {

constexpr double kDeg = std::numbers::pi / 180.0;

// 9 × 6 inner corners (cols + rows odd: the square colours fix the order), 25 mm squares.
constexpr const char* kTargetYaml = "type: chessboard\ncols: 9\nrows: 6\nsquare: 0.025\n";

inline pose::TargetSpec Board() {
  pose::TargetSpec target;
  target.type = pose::TargetType::kChessboard;
  target.cols = 9;
  target.rows = 6;
  target.square = 0.025;
  return target;
}

// One AprilTag (tag36h11 id 3, 100 mm), its centre the target origin (pose/target.h).
constexpr const char* kTagYaml = "type: apriltag\nfamily: tag36h11\nid: 3\nsize: 100\nunits: mm\n";

inline pose::TargetSpec Tag() {
  pose::TargetSpec target;
  target.type = pose::TargetType::kAprilTag;
  target.family = "tag36h11";
  target.id = 3;
  target.size = 0.1;
  return target;
}

inline pose::CameraModel TrueCamera() {
  return {.fx = 620.0,
          .fy = 622.0,
          .cx = 321.5,
          .cy = 238.0,
          .width = 640,
          .height = 480,
          .distortion = {-0.12, 0.05, 0.0, 0.0, 0.0}};
}

using ::hecal::testing::CameraYaml;

// T_camera_target of the camera `distance` from the target's centre (the board's by default),
// tilted by `tilt` towards `azimuth` (x right, y down on the board), looking at the centre and
// then panned by (pan_x, pan_y) radians about its own x and y axes so the target lands in
// different parts of the image (vision::testing::LookAt).
inline Pose ViewPose(double distance, double tilt, double azimuth, double pan_x, double pan_y,
                     const Eigen::Vector3d& centre = Eigen::Vector3d(0.1, 0.0625, 0.0)) {
  const Eigen::Vector3d eye =
      centre + distance * Eigen::Vector3d(std::sin(tilt) * std::cos(azimuth),
                                          std::sin(tilt) * std::sin(azimuth), -std::cos(tilt));
  return vision::testing::LookAt(eye, centre, Eigen::Vector2d(pan_x, pan_y));
}

// `count` views of a target centred at `centre` (the board's by default), tilted 15–35° in
// directions 60° apart, spread over the image, from `nearest` + (0, 1, 2)·`step` metres.
inline std::vector<Pose> Views(int count = 6, double nearest = 0.38, double step = 0.02,
                               const Eigen::Vector3d& centre = Eigen::Vector3d(0.1, 0.0625, 0.0)) {
  std::vector<Pose> views;
  for (int k = 0; k < count; ++k) {
    views.push_back(ViewPose(nearest + step * (k % 3), (15.0 + 10.0 * (k % 3)) * kDeg,
                             k * 60.0 * kDeg, (k % 2 == 0 ? 0.08 : -0.08),
                             (k % 4 < 2 ? 0.12 : -0.12), centre));
  }
  return views;
}

// The same for the tag (Tag()), from 0.3–0.4 m: the tag is 150–200 px across.
inline std::vector<Pose> TagViews(int count) {
  return Views(count, 0.3, 0.05, Eigen::Vector3d::Zero());
}

// Renders `target` (the board by default) seen from T_camera_target into `path` (slight blur and
// noise, as a real camera; `seed` for the noise), through `camera`.
inline void RenderView(const Pose& T_camera_target, std::uint64_t seed,
                       const std::filesystem::path& path, const pose::TargetSpec& target = Board(),
                       const pose::CameraModel& camera = TrueCamera()) {
  vision::RenderOptions options;
  options.blur_sigma = 0.6;
  options.noise_sigma = 1.0;
  options.supersampling = 4;
  options.seed = seed;
  cv::imwrite(path.string(), vision::RenderTarget(target, camera, T_camera_target, options));
}

// Renders every view into `dir` (created) as view_00.png, view_01.png, …, the noise of view i
// seeded with first_seed + i.
inline void RenderViewFolder(const std::filesystem::path& dir, const std::vector<Pose>& views,
                             std::uint64_t first_seed, const pose::TargetSpec& target = Board(),
                             const pose::CameraModel& camera = TrueCamera()) {
  std::filesystem::create_directories(dir);
  for (std::size_t i = 0; i < views.size(); ++i) {
    RenderView(views[i], first_seed + i, dir / ("view_0" + std::to_string(i) + ".png"), target,
               camera);
  }
}

// Rotation angle between two poses (deg) and translation distance (mm).
inline double RotationErrorDeg(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() / kDeg;
}
inline double TranslationErrorMm(const Pose& a, const Pose& b) {
  return 1e3 * (a.translation() - b.translation()).norm();
}

}  // namespace hecal::cli::rendered_views
