// Test support (not installed): the rendered-image scenes of the detection tests (src/vision) and
// of the CLI tests on images (apps/hecal), every choice an option: the camera (two presets
// beside image_scene.h's 640×480 and pose_scenes.h's 1280×960), the target (a 9 × 6 chessboard
// or a single AprilTag, with their target.yaml texts), the view poses T_camera_target, and
// whether to render each view (vision/render.h) and write it as a PNG.
//
// MakeRenderedScene gives per view the projected truth (testing/image_scene.h's StationImage:
// every object point of the target, index = id, and its pixel through pose::Project, lens
// distortion included) and, when `render`, the image: vision::RenderTarget with `rendering`,
// the noise of view i seeded with first_seed + i, so that the same options give the same images.
// With a `folder` the images are written there as <name>_00.png, <name>_01.png, … (the folder
// created; `name` is "view" by default). Frames and units: docs/conventions.md; metres, pixels,
// angles in degrees where a name says so, else radians.
//
// The view poses: FrontalView puts the target's centre on the optical axis and turns the
// target about the camera's axes; LookAtView places the camera on a sphere around a point of the
// target (LookAt) and pans it so the target lands in different parts of the image; SpreadViews
// is a set of such views (tilts 15–35° in directions 60° apart).
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"
#include "hecal/pose/target.h"
#include "hecal/vision/render.h"
#include "testing/image_scene.h"
#include "testing/target_specs.h"

namespace hecal::testing {

// 800 × 600 px, f = 700 px, principal point off-centre, the radial and tangential distortion of
// a typical machine-vision lens: the detection tests.
inline pose::CameraModel DetectionCamera() {
  return {700.0, 702.0, 401.3, 297.8, 800, 600, {-0.12, 0.05, 0.0008, -0.0005, 0.0}};
}

// 640 × 480 px, f ≈ 620 px, radial distortion only: the CLI tests on rendered images.
inline pose::CameraModel RenderCamera() {
  return {620.0, 622.0, 321.5, 238.0, 640, 480, {-0.12, 0.05, 0.0, 0.0, 0.0}};
}

// 9 × 6 inner corners (cols + rows odd: the square colours fix the order), 25 mm squares.
inline constexpr const char* kBoardYaml = "type: chessboard\ncols: 9\nrows: 6\nsquare: 0.025\n";

inline pose::TargetSpec Board() {
  return Chessboard(9, 6, 0.025);
}

// One AprilTag (tag36h11 id 3, 100 mm), its centre the target origin (pose/target.h).
inline constexpr const char* kTagYaml =
    "type: apriltag\nfamily: tag36h11\nid: 3\nsize: 100\nunits: mm\n";

inline pose::TargetSpec Tag() {
  pose::TargetSpec tag;
  tag.type = pose::TargetType::kAprilTag;
  tag.family = "tag36h11";
  tag.id = 3;
  tag.size = 0.1;
  return tag;
}

// The centre of the target's points (target frame).
inline Eigen::Vector3d TargetCentre(const pose::TargetSpec& target) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const std::vector<pose::ObjectPoint> points = pose::ObjectPoints(target);
  for (const pose::ObjectPoint& point : points) sum += point.position;
  return sum / static_cast<double>(points.size());
}

// T_camera_target with the target's centre on the optical axis at `distance`, the target turned
// by `roll_deg` about its normal and tilted by tilt_x_deg, tilt_y_deg about the camera's x and y
// axes (frontal at zero).
inline Pose FrontalView(const pose::TargetSpec& target, double distance, double tilt_x_deg,
                        double tilt_y_deg, double roll_deg) {
  const Eigen::Matrix3d R =
      (Eigen::AngleAxisd(tilt_x_deg * kRadiansPerDegree, Eigen::Vector3d::UnitX()) *
       Eigen::AngleAxisd(tilt_y_deg * kRadiansPerDegree, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(roll_deg * kRadiansPerDegree, Eigen::Vector3d::UnitZ()))
          .toRotationMatrix();
  return MakePose(R, Eigen::Vector3d(0.0, 0.0, distance) - R * TargetCentre(target));
}

// T_camera_target of a camera at `eye` (target frame) looking at `centre`, its x axis kept
// perpendicular to the target's y axis, then turned by `pan` (radians, about the camera's own x
// and y axes) so the target moves across the image. The target frame's z points into the board,
// so a camera on the board's front side sits at negative z.
inline Pose LookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& centre,
                   const Eigen::Vector2d& pan = Eigen::Vector2d::Zero()) {
  const Eigen::Vector3d z = (centre - eye).normalized();
  const Eigen::Vector3d x = Eigen::Vector3d::UnitY().cross(z).normalized();
  Eigen::Matrix3d R_target_camera;
  R_target_camera << x, z.cross(x), z;
  const Pose T_target_camera = MakePose(R_target_camera, eye);
  const Eigen::Matrix3d turn = (Eigen::AngleAxisd(pan.x(), Eigen::Vector3d::UnitX()) *
                                Eigen::AngleAxisd(pan.y(), Eigen::Vector3d::UnitY()))
                                   .toRotationMatrix();
  return MakePose(turn, Eigen::Vector3d::Zero()) * T_target_camera.inverse();
}

// The board's centre (Board(): 8 × 25 mm by 5 × 25 mm from its first corner).
inline Eigen::Vector3d BoardCentre() {
  return Eigen::Vector3d(0.1, 0.0625, 0.0);
}

// T_camera_target of the camera `distance` from `centre`, tilted by `tilt` towards `azimuth`
// (x right, y down on the target), looking at the centre and then panned by (pan_x, pan_y)
// about its own x and y axes.
inline Pose LookAtView(double distance, double tilt, double azimuth, double pan_x, double pan_y,
                       const Eigen::Vector3d& centre = BoardCentre()) {
  const Eigen::Vector3d eye =
      centre + distance * Eigen::Vector3d(std::sin(tilt) * std::cos(azimuth),
                                          std::sin(tilt) * std::sin(azimuth), -std::cos(tilt));
  return LookAt(eye, centre, Eigen::Vector2d(pan_x, pan_y));
}

// A set of LookAtViews: view k from nearest + (k mod 3)·step, tilted (15 + 10·(k mod 3))° towards
// azimuth k·60° + turn_deg, panned ±0.08 and ±0.12 rad so the target visits the image's quarters.
struct ViewSpread {
  int count = 6;
  double nearest = 0.38;  // m
  double step = 0.02;     // m
  double turn_deg = 0.0;  // added to every azimuth
  Eigen::Vector3d centre = BoardCentre();
};

inline std::vector<Pose> SpreadViews(const ViewSpread& spread = {}) {
  std::vector<Pose> views;
  for (int k = 0; k < spread.count; ++k) {
    views.push_back(LookAtView(
        spread.nearest + spread.step * (k % 3), (15.0 + 10.0 * (k % 3)) * kRadiansPerDegree,
        (k * 60.0 + spread.turn_deg) * kRadiansPerDegree, (k % 2 == 0 ? 0.08 : -0.08),
        (k % 4 < 2 ? 0.12 : -0.12), spread.centre));
  }
  return views;
}

// The spread for the tag (Tag()), from 0.3–0.4 m: the tag is 150–200 px across.
inline ViewSpread TagSpread(int count) {
  return {.count = count, .nearest = 0.3, .step = 0.05, .centre = Eigen::Vector3d::Zero()};
}

// The hand–eye rig of the rendered calibration tests: a camera 10 cm off the flange looking along
// the flange's x (RigX = T_gripper_camera), the board 60 cm in front of the robot base
// (RigZ = T_base_target). RigRobotPose gives the robot pose T_base_gripper = Z B⁻¹ X⁻¹ that
// makes the camera see the board from view B = T_camera_target (eye-in-hand: A X B = Z).
inline Pose RigX() {
  return MakePose(
      Eigen::AngleAxisd(100 * kRadiansPerDegree, Eigen::Vector3d(0.2, 1.0, -0.3).normalized())
          .toRotationMatrix(),
      Eigen::Vector3d(0.04, -0.03, 0.10));
}
inline Pose RigZ() {
  return MakePose(
      Eigen::AngleAxisd(170 * kRadiansPerDegree, Eigen::Vector3d(1.0, 0.1, 0.0).normalized())
          .toRotationMatrix(),
      Eigen::Vector3d(0.6, 0.1, 0.05));
}
inline Pose RigRobotPose(const Pose& T_camera_target) {
  return RigZ() * T_camera_target.inverse() * RigX().inverse();
}

// Pixel of every object point of `target` (index = id) seen from T_camera_target.
inline StationImage ProjectedTruth(const pose::TargetSpec& target, const pose::CameraModel& camera,
                                   const Pose& T_camera_target) {
  StationImage truth;
  for (const pose::ObjectPoint& point : pose::ObjectPoints(target)) {
    truth.target.push_back(point.position);
    truth.pixels.push_back(pose::Project(camera, T_camera_target * point.position));
  }
  return truth;
}

// Slight blur and noise, as a real camera.
inline vision::RenderOptions CameraLikeRendering() {
  vision::RenderOptions rendering;
  rendering.blur_sigma = 0.6;
  rendering.noise_sigma = 1.0;
  rendering.supersampling = 4;
  return rendering;
}

struct RenderedSceneOptions {
  pose::CameraModel camera = RenderCamera();
  pose::TargetSpec target = Board();
  std::vector<Pose> views = SpreadViews();  // T_camera_target, one per view
  bool render = true;
  vision::RenderOptions rendering = CameraLikeRendering();  // its seed is replaced per view
  std::uint64_t first_seed = 1;                             // view i: first_seed + i
  std::filesystem::path folder;  // where to write the PNGs; nothing written when empty
  std::string name = "view";     // view i is <name>_0<i>.png: view_00.png, view_01.png, …
};

struct RenderedScene {
  pose::CameraModel camera;
  pose::TargetSpec target;
  std::vector<Pose> views;
  std::vector<StationImage> truth;  // one per view
  std::vector<cv::Mat> images;      // one per view when rendered
  std::vector<std::string> files;   // the PNGs written, one per view
};

// The PNG name of view i: <name>_00.png … <name>_09.png, <name>_010.png, …
inline std::string ViewFileName(const std::string& name, std::size_t i) {
  return name + "_0" + std::to_string(i) + ".png";
}

inline RenderedScene MakeRenderedScene(const RenderedSceneOptions& options) {
  RenderedScene scene{options.camera, options.target, options.views, {}, {}, {}};
  if (!options.folder.empty()) std::filesystem::create_directories(options.folder);
  for (std::size_t i = 0; i < options.views.size(); ++i) {
    scene.truth.push_back(ProjectedTruth(options.target, options.camera, options.views[i]));
    if (!options.render) continue;
    vision::RenderOptions rendering = options.rendering;
    rendering.seed = options.first_seed + i;
    scene.images.push_back(
        vision::RenderTarget(options.target, options.camera, options.views[i], rendering));
    if (options.folder.empty()) continue;
    scene.files.push_back((options.folder / ViewFileName(options.name, i)).string());
    cv::imwrite(scene.files.back(), scene.images.back());
  }
  return scene;
}

}  // namespace hecal::testing
