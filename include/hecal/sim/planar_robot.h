// Simulated planar robots (handeye/planar.h, docs/planar.md): a SCARA-like arm whose flange
// turns about the base's vertical axis only, for the planar calibration's tests and study.
//
// Station i: T_base_gripper_i = Trans(x_i, y_i, z_i) · Rz(θ_i) · F with F = Rx(π) (the flange
// looks down), x_i, y_i ~ U(−0.15, 0.15) m about the work point (0.5, 0, 0), z_i ~ U(0.35, 0.45) m
// and θ_i ~ U(−90°, 90°): every relative rotation is about the gripper's z axis, so X's
// translation along it cannot be observed (planar.h).
//   eye-in-hand: X = T_gripper_camera = (a few degrees of tilt, (0.04, −0.03, 0.06) m), the
//                camera looking down; Z = T_base_target, the board on the table at the work point.
//   eye-to-hand: X = T_base_camera, a camera 0.8 m above the work point looking down; Z =
//                T_gripper_target, a board below the flange, 0.1 m out.
// Noise as the thesis protocol's: right perturbations of every robot pose and camera pose
// (sim/noise.h).
#pragma once

#include <random>

#include "hecal/handeye/problem.h"
#include "hecal/sim/noise.h"

namespace hecal::sim {

struct PlanarScene {
  handeye::Problem truth;     // noise-free
  handeye::Problem measured;  // with noise
  Pose X = Pose::Identity();
  Pose Z = Pose::Identity();
  std::vector<Pose> T_base_gripper;   // measured, for writing pose files
  std::vector<Pose> T_camera_target;  // measured
};

PlanarScene DrawPlanarScene(handeye::Setup setup, int stations, const NoiseModel& robot_noise,
                            const NoiseModel& camera_noise, std::mt19937_64& rng);

}  // namespace hecal::sim
