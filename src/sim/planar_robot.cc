// Simulated planar robots (planar_robot.h).
#include "hecal/sim/planar_robot.h"

#include <Eigen/Geometry>
#include <numbers>

#include "hecal/core/random_draws.h"

namespace hecal::sim {
namespace {

Pose Rotation(const Eigen::Vector3d& axis, double angle) {
  return MakePose(Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(),
                  Eigen::Vector3d::Zero());
}

Pose Translation(double x, double y, double z) {
  return MakePose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(x, y, z));
}

}  // namespace

PlanarScene DrawPlanarScene(handeye::Setup setup, int stations, const NoiseModel& robot_noise,
                            const NoiseModel& camera_noise, std::mt19937_64& rng) {
  constexpr double kPi = std::numbers::pi;
  hecal::UniformRealDistribution lateral(-0.15, 0.15);
  hecal::UniformRealDistribution height(0.35, 0.45);
  hecal::UniformRealDistribution turn(-kPi / 2.0, kPi / 2.0);
  const Pose flange_down = Rotation(Eigen::Vector3d::UnitX(), kPi);
  PlanarScene scene;
  scene.truth.setup = scene.measured.setup = setup;
  if (setup == handeye::Setup::kEyeInHand) {
    scene.X = Translation(0.04, -0.03, 0.06) * Rotation(Eigen::Vector3d(1.0, 2.0, 0.5), 0.06);
    scene.Z = Translation(0.5, 0.0, 0.0) * Rotation(Eigen::Vector3d::UnitZ(), 0.3) * flange_down;
  } else {
    scene.X =
        Translation(0.5, 0.05, 1.2) * Rotation(Eigen::Vector3d(0.3, 1.0, 0.0), 0.05) * flange_down;
    scene.Z = Translation(0.1, 0.0, 0.05) * Rotation(Eigen::Vector3d::UnitZ(), 0.4);
  }
  for (int i = 0; i < stations; ++i) {
    // One draw at a time, in the order of the data sets' first generation (turn first).
    const double angle = turn(rng);
    const double z = height(rng);
    const double y = lateral(rng);
    const double x = 0.5 + lateral(rng);
    const Pose T_base_gripper =
        Translation(x, y, z) * Rotation(Eigen::Vector3d::UnitZ(), angle) * flange_down;
    // Z = A X B with A = T_base_gripper (eye-in-hand) or its inverse (eye-to-hand).
    const Pose A = setup == handeye::Setup::kEyeInHand ? T_base_gripper : T_base_gripper.inverse();
    const Pose T_camera_target = (A * scene.X).inverse() * scene.Z;
    const Pose robot = AddNoise(T_base_gripper, robot_noise, rng);
    const Pose camera = AddNoise(T_camera_target, camera_noise, rng);
    scene.T_base_gripper.push_back(robot);
    scene.T_camera_target.push_back(camera);
    scene.truth.A.push_back(A);
    scene.truth.B.push_back(T_camera_target);
    scene.measured.A.push_back(setup == handeye::Setup::kEyeInHand ? robot : robot.inverse());
    scene.measured.B.push_back(camera);
  }
  return scene;
}

}  // namespace hecal::sim
