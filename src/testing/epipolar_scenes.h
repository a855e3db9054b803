// Test support (not installed): synthetic target-free scenes for the global method — robot
// stations, a random X = T_hand_camera, scene points seen from both stations of each motion,
// bearings from a pinhole camera with optional pixel noise and wrong matches.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <random>
#include <vector>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/so3.h"
#include "hecal/global/epipolar_problem.h"
#include "testing/random_poses.h"

namespace hecal::testing {

struct EpipolarSceneSpec {
  int motions = 5;
  int pairs = 50;               // per motion
  double rotation = 0.6;        // radians: robot rotation between the stations of a motion
  double step = 0.3;            // metres: robot translation between the stations
  double depth = 1.0;           // metres: mean scene depth in front of the first camera
  double focal = 1000.0;        // pixels
  double pixel_sigma = 0.0;     // pixels, per axis
  double wrong_fraction = 0.0;  // share of pairs whose second ray points at another point
  bool planar = false;          // scene points on one plane (z = depth in the first camera)
  // Robot pose error as the robot gives it (estimation/pose_sigma.h): the poses of the robot file
  // are the true T_base_gripper times (Exp(ω), τ), ω and τ normal with these standard deviations
  // per axis (radians, metres) — eye-in-hand a right perturbation of the hand pose H itself,
  // eye-to-hand (H = T_base_gripper⁻¹) a left one of H; the images are taken at the true poses.
  double robot_rotation_sigma = 0.0;
  double robot_translation_sigma = 0.0;
  handeye::Setup setup = handeye::Setup::kEyeInHand;
};

struct EpipolarScene {
  global::EpipolarProblem problem;
  Pose X = Pose::Identity();             // T_hand_camera, the truth
  std::vector<Pose> T_base_gripper;      // two stations per motion
  std::vector<std::vector<bool>> wrong;  // per motion and pair
};

// A bearing from a point in the camera frame through the pinhole camera with pixel noise.
inline Eigen::Vector3d NoisyBearing(const Eigen::Vector3d& p, double focal, double sigma,
                                    std::mt19937_64& rng) {
  hecal::NormalDistribution normal(0.0, sigma);
  const double x = p.x() / p.z() + (sigma > 0 ? normal(rng) / focal : 0.0);
  const double y = p.y() / p.z() + (sigma > 0 ? normal(rng) / focal : 0.0);
  return Eigen::Vector3d(x, y, 1.0).normalized();
}

inline EpipolarScene MakeEpipolarScene(const EpipolarSceneSpec& spec, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  hecal::UniformRealDistribution uniform(-1.0, 1.0);
  EpipolarScene scene;
  scene.problem.setup = spec.setup;
  // Draws within a statement run last to first: the order these tests' data were generated in.
  const double tz = uniform(rng);
  const double ty = uniform(rng);
  const double tx = uniform(rng);
  scene.X = MakePose(RandomRotation(rng), 0.2 * Eigen::Vector3d(tx, ty, tz));
  const Pose H0 = MakePose(RandomRotation(rng), Eigen::Vector3d(0.5, 0.1, 0.6));
  for (int m = 0; m < spec.motions; ++m) {
    global::EpipolarMotion motion;
    motion.first_station = 2 * m;
    motion.second_station = 2 * m + 1;
    const double hz = uniform(rng);
    const double hy = uniform(rng);
    const double hx = uniform(rng);
    const Pose H_first =
        H0 * MakePose(so3::Exp(RandomRotationVector(rng, 0.3)), 0.1 * Eigen::Vector3d(hx, hy, hz));
    Pose H_second = Pose::Identity();
    std::vector<Eigen::Vector3d> points;  // in the first camera frame
    for (int attempt = 0; attempt < 100; ++attempt) {
      const Eigen::Vector3d axis = RandomUnitVector(rng);
      const double angle = spec.rotation * (0.7 + 0.3 * std::abs(uniform(rng)));
      H_second = H_first * MakePose(so3::Exp(angle * axis), spec.step * RandomUnitVector(rng));
      const Pose camera_motion = global::CameraMotion(scene.X, H_first.inverse() * H_second);
      points.clear();
      for (int tries = 0; tries < 50 * spec.pairs && int(points.size()) < spec.pairs; ++tries) {
        const double z =
            spec.planar ? spec.depth : spec.depth * (0.6 + 0.8 * std::abs(uniform(rng)));
        const double v = uniform(rng);
        const double u = uniform(rng);
        const Eigen::Vector3d p(0.5 * z * u, 0.4 * z * v, z);
        const Eigen::Vector3d q = camera_motion.inverse() * p;  // second camera frame
        if (q.z() > 0.2 && std::abs(q.x() / q.z()) < 0.6 && std::abs(q.y() / q.z()) < 0.5) {
          points.push_back(p);
        }
      }
      if (int(points.size()) == spec.pairs) break;
    }
    const Pose camera_motion = global::CameraMotion(scene.X, H_first.inverse() * H_second);
    const auto measured = [&](const Pose& H) {
      if (spec.robot_rotation_sigma <= 0.0 && spec.robot_translation_sigma <= 0.0) return H;
      hecal::NormalDistribution normal(0.0, 1.0);
      const double omega_z = normal(rng), omega_y = normal(rng), omega_x = normal(rng);
      const Eigen::Vector3d omega(omega_x, omega_y, omega_z);
      const double tau_z = normal(rng), tau_y = normal(rng), tau_x = normal(rng);
      const Eigen::Vector3d tau(tau_x, tau_y, tau_z);
      const Pose error =
          MakePose(so3::Exp(spec.robot_rotation_sigma * omega), spec.robot_translation_sigma * tau);
      return spec.setup == handeye::Setup::kEyeInHand ? Pose(H * error)
                                                      : Pose((H.inverse() * error).inverse());
    };
    const Pose H_first_measured = measured(H_first);
    const Pose H_second_measured = measured(H_second);
    motion.hand = H_first_measured.inverse() * H_second_measured;
    std::vector<bool> wrong(points.size(), false);
    for (std::size_t j = 0; j < points.size(); ++j) {
      const Eigen::Vector3d& p = points[j];
      Eigen::Vector3d q = camera_motion.inverse() * p;
      if (hecal::UniformRealDistribution(0, 1)(rng) < spec.wrong_fraction) {
        wrong[j] = true;
        const Eigen::Vector3d& other =
            points[(j + 1 + rng() % (points.size() - 1)) % points.size()];
        q = camera_motion.inverse() * other;
      }
      motion.pairs.push_back({NoisyBearing(p, spec.focal, spec.pixel_sigma, rng),
                              NoisyBearing(q, spec.focal, spec.pixel_sigma, rng), int(j)});
    }
    // The robot poses as the robot file would give them.
    const Pose G_first =
        spec.setup == handeye::Setup::kEyeInHand ? H_first_measured : H_first_measured.inverse();
    const Pose G_second =
        spec.setup == handeye::Setup::kEyeInHand ? H_second_measured : H_second_measured.inverse();
    scene.T_base_gripper.push_back(G_first);
    scene.T_base_gripper.push_back(G_second);
    scene.wrong.push_back(wrong);
    scene.problem.motions.push_back(std::move(motion));
  }
  return scene;
}

// Angle between two rotations and distance between two translations.
inline double RotationError(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

}  // namespace hecal::testing
