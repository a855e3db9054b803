// Test and benchmark support (not installed): synthetic camera-pose problems with known truth for
// the pose-from-known-points methods (pose/*.h). A 1280×960 camera (f ≈ 1000 px, mild plumb_bob
// distortion) looks at an object 1 m away: N points uniform in a 0.4 m cube, or on a 0.4 m square
// (z = 0 in the target frame, OpenCV's board frame) tilted up to 40° from fronto-parallel. The
// object's centre is up to 0.1 m off the optical axis (a corner of a turned cube may project a
// little outside the 1280×960 frame; the model is defined there too); its rotation is uniform on
// SO(3) for a volume, a random tilt about a random in-plane axis plus a free spin for a plane.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"
#include "testing/random_poses.h"

namespace hecal::testing {

inline pose::CameraModel SceneCamera() {
  pose::CameraModel camera;
  camera.fx = 1000.0;
  camera.fy = 995.0;
  camera.cx = 641.5;
  camera.cy = 478.0;
  camera.width = 1280;
  camera.height = 960;
  camera.distortion = {-0.08, 0.05, 4e-4, -3e-4, 0.0};
  return camera;
}

struct PoseScene {
  pose::CameraModel camera;
  Pose T_camera_target = Pose::Identity();  // the truth
  std::vector<Eigen::Vector3d> object_points;
  std::vector<Eigen::Vector2d> pixels;  // exact projections
};

enum class SceneShape { kVolume, kPlane };

inline PoseScene RandomScene(std::mt19937_64& rng, int points, SceneShape shape,
                             const pose::CameraModel& camera = SceneCamera()) {
  constexpr double kSide = 0.4, kDistance = 1.0, kLateral = 0.1;
  constexpr double kMaxTilt = 40.0 * std::numbers::pi / 180.0;
  std::uniform_real_distribution<double> side(-kSide / 2, kSide / 2), lateral(-kLateral, kLateral);
  std::uniform_real_distribution<double> tilt(0.0, kMaxTilt),
      spin(-std::numbers::pi, std::numbers::pi);
  PoseScene scene;
  scene.camera = camera;
  for (int k = 0; k < points; ++k) {
    scene.object_points.emplace_back(side(rng), side(rng),
                                     shape == SceneShape::kVolume ? side(rng) : 0.0);
  }
  Eigen::Matrix3d R;
  if (shape == SceneShape::kVolume) {
    R = RandomRotation(rng);
  } else {
    const double heading = spin(rng);
    const Eigen::Vector3d in_plane_axis(std::cos(heading), std::sin(heading), 0.0);
    R = Eigen::AngleAxisd(tilt(rng), in_plane_axis).toRotationMatrix() *
        Eigen::AngleAxisd(spin(rng), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  }
  // The object's centre (origin of the target frame) at the chosen place in front of the camera.
  scene.T_camera_target = MakePose(R, Eigen::Vector3d(lateral(rng), lateral(rng), kDistance));
  for (const Eigen::Vector3d& P : scene.object_points) {
    scene.pixels.push_back(pose::Project(camera, scene.T_camera_target * P));
  }
  return scene;
}

inline std::vector<Eigen::Vector2d> AddPixelNoise(std::mt19937_64& rng,
                                                  const std::vector<Eigen::Vector2d>& pixels,
                                                  double sigma) {
  std::normal_distribution<double> normal(0.0, sigma);
  std::vector<Eigen::Vector2d> noisy = pixels;
  if (sigma > 0.0) {
    for (Eigen::Vector2d& u : noisy) u += Eigen::Vector2d(normal(rng), normal(rng));
  }
  return noisy;
}

}  // namespace hecal::testing
