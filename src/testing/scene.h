// Test support (not installed): the one synthetic hand–eye scene generator of the tests, built on
// handeye (and geometry) only, so that the solver tests below `sim` do not depend on it.
//
// A scene is a set of stations with known truth, following the thesis protocol
// (docs/thesis-study.md) with every distance an option:
//  - X and Z: uniformly random rotations; translations uniform per axis in ±hand_eye_offset for
//    the flange offset (X eye-in-hand, Z eye-to-hand) and ±other_offset for the other unknown;
//  - each station's camera, in the target frame (z into the board): position uniform in a cube of
//    side `cube_side` centred `start_distance` in front of the target, orientation
//    Rx(α)·Ry(β)·Rz(γ) with α, β ~ U(−max_tilt, max_tilt) and the spin γ ~ U(−π, π);
//  - robot poses from Z = A_i X B_i (handeye/problem.h; A_i = T_base_gripper_i eye-in-hand, its
//    inverse eye-to-hand), then Gaussian noise on every measured pose, right perturbation
//    T·Exp(δ) with δ = (ω, v), ω_k ~ N(0, σ_r²) rad, v_k ~ N(0, σ_t²) m (docs/conventions.md).
// Noise is drawn after the truth, so a scene's noise-free poses do not depend on the noise.
#pragma once

#include <algorithm>
#include <numbers>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/euler.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"
#include "testing/random_poses.h"

namespace hecal::testing {

// Isotropic Gaussian pose noise: σ_r in radians per rotation component, σ_t in metres per
// translation component.
struct PoseNoise {
  double rotation_sigma = 0.0;
  double translation_sigma = 0.0;
};

struct SceneOptions {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  int stations = 15;
  double start_distance = 1.0;           // metres, camera to target
  double cube_side = 1.0;                // metres, the cube of camera positions
  double max_tilt = 0.7853981633974483;  // radians (45°), about the image-plane axes
  double hand_eye_offset = 0.05;         // metres, |translation component| of the flange offset
  double other_offset = 1.0;             // metres, |translation component| of the other unknown
  PoseNoise robot_noise;                 // on T_base_gripper
  PoseNoise camera_noise;                // on T_camera_target
};

// Stations with their truth. X, Z and the poses have handeye/problem.h's meaning for `setup`.
struct Scene {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  Pose X = Pose::Identity();
  Pose Z = Pose::Identity();
  std::vector<Pose> T_base_gripper_true;
  std::vector<Pose> T_camera_target_true;
  std::vector<Pose> T_base_gripper;   // measured
  std::vector<Pose> T_camera_target;  // measured

  handeye::Problem MeasuredProblem() const {
    return handeye::MakeProblem(setup, T_base_gripper, T_camera_target);
  }
  handeye::Problem TrueProblem() const {
    return handeye::MakeProblem(setup, T_base_gripper_true, T_camera_target_true);
  }
};

// T·Exp(δ), δ drawn as above; T itself when both σ are zero (no draws).
inline Pose AddPoseNoise(const Pose& T, const PoseNoise& noise, std::mt19937_64& rng) {
  if (noise.rotation_sigma == 0.0 && noise.translation_sigma == 0.0) return T;
  Vector6d delta;
  for (int k = 0; k < 6; ++k) {
    delta(k) =
        (k < 3 ? noise.rotation_sigma : noise.translation_sigma) * hecal::NormalDistribution()(rng);
  }
  return T * se3::Exp(delta);
}

namespace scene_internal {

// T_target_camera of one station (scene.h): tilt α, β, spin γ, then the position in the cube.
inline Pose CameraInTarget(const SceneOptions& options, std::mt19937_64& rng) {
  hecal::UniformRealDistribution tilt(-options.max_tilt, options.max_tilt);
  hecal::UniformRealDistribution spin(-std::numbers::pi, std::numbers::pi);
  // One declaration, evaluated in order: α, β about the image-plane axes, then the spin γ.
  const double alpha = tilt(rng), beta = tilt(rng), gamma = spin(rng);
  const Eigen::Vector3d start(0.0, 0.0, -options.start_distance);
  return MakePose(
      ElementaryRotation(0, alpha) * ElementaryRotation(1, beta) * ElementaryRotation(2, gamma),
      start + RandomPointInBox(rng, 0.5 * options.cube_side));
}

}  // namespace scene_internal

inline Scene MakeScene(const SceneOptions& options, std::mt19937_64& rng) {
  Scene scene;
  scene.setup = options.setup;
  const bool in_hand = options.setup == handeye::Setup::kEyeInHand;
  // The flange offset is the small one: X eye-in-hand (camera on the flange), Z eye-to-hand.
  scene.X = RandomPose(rng, in_hand ? options.hand_eye_offset : options.other_offset);
  scene.Z = RandomPose(rng, in_hand ? options.other_offset : options.hand_eye_offset);
  const Pose X_inverse = scene.X.inverse();
  for (int i = 0; i < options.stations; ++i) {
    const Pose T_target_camera = scene_internal::CameraInTarget(options, rng);
    const Pose A = scene.Z * T_target_camera * X_inverse;  // Z = A X B
    scene.T_base_gripper_true.push_back(in_hand ? A : A.inverse());
    scene.T_camera_target_true.push_back(T_target_camera.inverse());
  }
  for (int i = 0; i < options.stations; ++i) {
    const auto k = static_cast<size_t>(i);
    scene.T_base_gripper.push_back(
        AddPoseNoise(scene.T_base_gripper_true[k], options.robot_noise, rng));
    scene.T_camera_target.push_back(
        AddPoseNoise(scene.T_camera_target_true[k], options.camera_noise, rng));
  }
  return scene;
}

// Gross outliers: replaces the measured robot pose of `count` distinct stations (drawn uniformly)
// by a pose with a uniform rotation and a translation uniform in [−1, 1]³ m; the camera poses
// stay. Returns the replaced stations, ascending. Requires 0 ≤ count ≤ the number of stations.
inline std::vector<int> ReplaceRobotPoses(Scene* scene, int count, std::mt19937_64& rng) {
  const int n = static_cast<int>(scene->T_base_gripper.size());
  if (count < 0 || count > n) {
    throw std::invalid_argument("ReplaceRobotPoses: count must be within [0, stations]");
  }
  std::vector<int> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  for (size_t i = 0; i < static_cast<size_t>(count); ++i) {  // a partial Fisher–Yates shuffle
    std::swap(order[i], order[static_cast<size_t>(
                            std::uniform_int_distribution<int>(static_cast<int>(i), n - 1)(rng))]);
  }
  std::vector<int> stations(order.begin(), order.begin() + count);
  std::sort(stations.begin(), stations.end());
  for (const int i : stations) {
    const Eigen::Matrix3d R = RandomRotation(rng);  // rotation first, then translation
    scene->T_base_gripper[static_cast<size_t>(i)] = MakePose(R, RandomPointInBox(rng, 1.0));
  }
  return stations;
}

}  // namespace hecal::testing
