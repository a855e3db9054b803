// Test support (not installed): hand–eye data sets with known truth for solver tests.
//  - ThesisCase: the thesis protocol (testing/scene.h), optionally noisy.
//  - WideRotationCase: every consecutive station pair differs by a rotation of 170°–179.9°
//    (the data that break OpenCV 4.6's TSAI / HORAUD / DANIILIDIS), plus a hand–eye rotation
//    chosen by the caller (e.g. exactly π, to stress Tsai's tan(θ/2)).
#pragma once

#include <numbers>
#include <random>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/so3.h"
#include "hecal/handeye/problem.h"
#include "testing/random_poses.h"
#include "testing/scene.h"

namespace hecal::testing {

inline Scene ThesisCase(handeye::Setup setup, int stations, uint64_t seed,
                        double rotation_sigma = 0.0, double translation_sigma = 0.0) {
  std::mt19937_64 rng(seed);
  SceneOptions options;
  options.setup = setup;
  options.stations = stations;
  options.robot_noise = options.camera_noise = {rotation_sigma, translation_sigma};
  return MakeScene(options, rng);
}

// Noise-free; station k+1 = station k rotated by 170°–179.9° about a random axis (relative
// rotations of consecutive stations in that range). X's rotation angle is `x_angle` about a
// random axis (default random rotation when negative).
inline Scene WideRotationCase(handeye::Setup setup, int stations, uint64_t seed,
                              double x_angle = -1.0) {
  std::mt19937_64 rng(seed);
  hecal::UniformRealDistribution angle(170.0, 179.9);
  Scene data;
  data.setup = setup;
  const Pose small = RandomPose(rng, 0.05);
  const Pose large = RandomPose(rng, 1.0);
  Pose X = setup == handeye::Setup::kEyeInHand ? small : large;
  if (x_angle >= 0.0) X.linear() = so3::Exp(RandomRotationVector(rng, x_angle));
  data.X = X;
  data.Z = setup == handeye::Setup::kEyeInHand ? large : small;
  Pose T_target_camera = MakePose(RandomRotation(rng), Eigen::Vector3d(0.0, 0.0, -1.0));
  for (int i = 0; i < stations; ++i) {
    if (i > 0) {
      const double theta = angle(rng) * std::numbers::pi / 180.0;
      T_target_camera.linear() =
          T_target_camera.linear() * so3::Exp(RandomRotationVector(rng, theta));
      hecal::UniformRealDistribution box(-0.5, 0.5);
      const double z = box(rng);  // drawn last to first, as the tests' data were generated
      const double y = box(rng);
      const double x = box(rng);
      T_target_camera.translation() = Eigen::Vector3d(x, y, -1.0 + z);
    }
    const Pose B = T_target_camera.inverse();
    const Pose A = data.Z * T_target_camera * X.inverse();
    const Pose G = setup == handeye::Setup::kEyeInHand ? A : A.inverse();
    data.T_base_gripper_true.push_back(G);
    data.T_camera_target_true.push_back(B);
  }
  data.T_base_gripper = data.T_base_gripper_true;
  data.T_camera_target = data.T_camera_target_true;
  return data;
}

// Errors of an estimate against the truth: rotation angle (rad) and translation distance (m).
struct PoseError {
  double rotation;
  double translation;
};
inline PoseError Error(const Pose& estimate, const Pose& truth) {
  return {so3::Distance(estimate.linear(), truth.linear()),
          (estimate.translation() - truth.translation()).norm()};
}

}  // namespace hecal::testing
