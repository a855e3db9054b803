// Test support (not installed, no OpenCV): synthetic target-free scenes shaped like
// data/rwhe-kuka2 (Ali et al. 2019; SOURCE.md) for the global method's polish. The robot's 28
// eye-in-hand poses (RobotPosesVec.txt: row-major 4 × 4 T_base_gripper, metres) are taken as the
// true hand poses; X = T_gripper_camera is the `ml` result on the real corners (docs/global.md,
// "Measured"); the camera is the reference pinhole (f ≈ 1056 px, 1920 × 1200; distortion is not
// simulated: the bearings are exact rays). The scene is a flat 24 × 17 grid of 15 mm (the board's
// inner corners) facing the cameras at the point nearest to all optical axes. The 27 motions
// join consecutive stations (18 of them pure 10° rotations of the gripper about its own x axis,
// 9 translating by 86–213 mm). Each image sees the corners once (one ray noise per corner and
// image, shared by the two motions that use the image); the problem is given each station's pose
// with a robot error (Exp(ω), τ) on the right, ω and τ normal per axis, drawn once per station
// and so shared by the two motions that use it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/so3.h"
#include "hecal/geometry/types.h"
#include "hecal/global/epipolar_problem.h"

namespace hecal::testing::kuka2 {

// RobotPosesVec.txt: T_base_gripper of each of the 28 images (empty when unreadable).
inline std::vector<Pose> RobotPoses() {
  std::vector<Pose> robot;
  std::ifstream file(std::string(HECAL_SOURCE_DIR) + "/data/rwhe-kuka2/RobotPosesVec.txt");
  Eigen::Matrix4d M;
  while (true) {
    for (int k = 0; k < 16; ++k) file >> M(k / 4, k % 4);
    if (!file) break;
    robot.emplace_back(M);
  }
  return robot;
}

// `ml`'s X on the real corners: 121.656° about (−0.5692, 0.6045, −0.5573), t in metres.
inline Pose MlX() {
  const Eigen::Vector3d axis = Eigen::Vector3d(-0.5692, 0.6045, -0.5573).normalized();
  return MakePose(so3::Exp(121.656 * M_PI / 180.0 * axis),
                  Eigen::Vector3d(0.01438, -0.10806, -0.08169));
}

struct SceneSpec {
  double ray_sigma = 3.7e-5;                         // radians per image axis
  double robot_rotation_sigma = 0.025 * M_PI / 180;  // radians per axis, per station
  double robot_translation_sigma = 0.08e-3;          // metres per axis, per station
  int pairs = 20;                                    // per motion, evenly spaced in corner id
};

struct Scene {
  global::EpipolarProblem problem;  // eye-in-hand, stations 0..27, motions (k, k + 1)
  Pose X = Pose::Identity();        // the truth
};

inline Scene MakeScene(const SceneSpec& spec, std::uint64_t seed) {
  constexpr double kFocal = 1056.35, kCx = 958.8, kCy = 586.9, kWidth = 1920, kHeight = 1200;
  std::mt19937_64 rng(seed);
  hecal::NormalDistribution normal(0.0, 1.0);
  Scene scene;
  scene.problem.setup = handeye::Setup::kEyeInHand;
  scene.X = MlX();
  const std::vector<Pose> hands = RobotPoses();
  std::vector<Pose> cameras;
  for (const Pose& H : hands) cameras.push_back(H * scene.X);
  // The board's centre: least squares nearest to every optical axis; its normal: towards the
  // cameras (minus their mean viewing direction).
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero(), view = Eigen::Vector3d::Zero();
  for (const Pose& C : cameras) {
    const Eigen::Vector3d d = C.linear().col(2);
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - d * d.transpose();
    A += P;
    b += P * C.translation();
    view += d;
  }
  const Eigen::Vector3d centre = A.ldlt().solve(b);
  const Eigen::Vector3d normal_axis = -view.normalized();
  const Eigen::Vector3d across = normal_axis.unitOrthogonal();
  const Eigen::Vector3d down = normal_axis.cross(across);
  std::vector<Eigen::Vector3d> corners;  // base frame, id = index
  for (int row = 0; row < 17; ++row) {
    for (int col = 0; col < 24; ++col) {
      corners.push_back(centre + 0.015 * ((col - 11.5) * across + (row - 8) * down));
    }
  }
  // Per image: the noisy ray of every corner it sees (zero vector where it does not).
  std::vector<std::vector<Eigen::Vector3d>> rays(cameras.size());
  for (std::size_t j = 0; j < cameras.size(); ++j) {
    for (const Eigen::Vector3d& corner : corners) {
      const Eigen::Vector3d p = cameras[j].inverse() * corner;
      const double u = kCx + kFocal * p.x() / p.z(), v = kCy + kFocal * p.y() / p.z();
      const bool seen = p.z() > 0 && u >= 0 && u <= kWidth - 1 && v >= 0 && v <= kHeight - 1;
      // Draws run last to first (y before x): the order the tests' data were generated in.
      const double noise_y = normal(rng);
      const double noise_x = normal(rng);
      const Eigen::Vector3d noisy(p.x() / p.z() + spec.ray_sigma * noise_x,
                                  p.y() / p.z() + spec.ray_sigma * noise_y, 1.0);
      rays[j].push_back(seen ? Eigen::Vector3d(noisy.normalized()) : Eigen::Vector3d::Zero());
    }
  }
  std::vector<Pose> measured;
  for (const Pose& H : hands) {
    const double omega_z = normal(rng), omega_y = normal(rng), omega_x = normal(rng);
    const Eigen::Vector3d omega(omega_x, omega_y, omega_z);
    const double tau_z = normal(rng), tau_y = normal(rng), tau_x = normal(rng);
    const Eigen::Vector3d tau(tau_x, tau_y, tau_z);
    measured.push_back(H * MakePose(so3::Exp(spec.robot_rotation_sigma * omega),
                                    spec.robot_translation_sigma * tau));
  }
  for (std::size_t j = 0; j + 1 < hands.size(); ++j) {
    global::EpipolarMotion motion;
    motion.first_station = int(j);
    motion.second_station = int(j + 1);
    motion.hand = measured[j].inverse() * measured[j + 1];
    std::vector<int> both;
    for (std::size_t id = 0; id < corners.size(); ++id) {
      if (rays[j][id].norm() > 0 && rays[j + 1][id].norm() > 0) both.push_back(int(id));
    }
    const int n = std::min(spec.pairs, int(both.size()));
    for (int k = 0; k < n; ++k) {
      const int id = both[std::size_t(k) * both.size() / std::size_t(n)];
      motion.pairs.push_back({rays[j][std::size_t(id)], rays[j + 1][std::size_t(id)], id});
    }
    scene.problem.motions.push_back(std::move(motion));
  }
  return scene;
}

}  // namespace hecal::testing::kuka2
