// Test support (not installed): hand–eye stations with images of a planar grid target, for the
// reprojection tests. A compact scene (testing/scene.h: camera 1 m from the target, 0.4 m cube,
// ±20° tilt, free spin) keeps every target point in front of every camera; the camera is a 640×480
// pinhole with mild plumb_bob distortion; the target is a 9 × 6 grid of 30 mm pitch.
#pragma once

#include <random>
#include <vector>

#include "hecal/estimation/reprojection_refinement.h"
#include "hecal/pose/camera_model.h"
#include "testing/scene.h"

namespace hecal::testing {

inline pose::CameraModel TestCamera() {
  pose::CameraModel camera;
  camera.fx = 800.0;
  camera.fy = 805.0;
  camera.cx = 321.0;
  camera.cy = 238.0;
  camera.width = 640;
  camera.height = 480;
  camera.distortion = {-0.12, 0.08, 0.0005, -0.0003, 0.0};
  return camera;
}

inline std::vector<Eigen::Vector3d> GridTarget() {
  std::vector<Eigen::Vector3d> points;
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 9; ++c) points.emplace_back(0.03 * c - 0.12, 0.03 * r - 0.075, 0.0);
  }
  return points;
}

struct ImageStations {
  Scene data;                                   // truth and (noisy) robot poses
  std::vector<estimation::ImagePoints> images;  // pixels of the TRUE camera poses + pixel noise
};

// `robot_noise` perturbs the robot poses (right perturbation); pixels get isotropic Gaussian
// noise `pixel_sigma` (px).
inline ImageStations MakeImageStations(handeye::Setup setup, int stations, uint64_t seed,
                                       const PoseNoise& robot_noise, double pixel_sigma) {
  std::mt19937_64 rng(seed);
  SceneOptions options;
  options.setup = setup;
  options.stations = stations;
  options.cube_side = 0.4;
  options.max_tilt = 20.0 * 3.14159265358979323846 / 180.0;
  options.robot_noise = robot_noise;
  ImageStations out{MakeScene(options, rng), {}};
  const pose::CameraModel camera = TestCamera();
  std::normal_distribution<double> noise(0.0, 1.0);
  for (const Pose& B : out.data.T_camera_target_true) {
    estimation::ImagePoints image;
    for (const Eigen::Vector3d& P : GridTarget()) {
      image.target.push_back(P);
      const Eigen::Vector2d n(noise(rng), noise(rng));
      image.pixels.push_back(pose::Project(camera, B * P) + pixel_sigma * n);
    }
    out.images.push_back(std::move(image));
  }
  return out;
}

}  // namespace hecal::testing
