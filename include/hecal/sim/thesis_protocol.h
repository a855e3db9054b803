// Synthetic hand–eye data sets following the thesis protocol (docs/thesis-study.md):
//  - ground-truth hand–eye transform: uniformly random rotation, translation U(−50, 50) mm per
//    axis (the camera's offset from the flange for eye-in-hand, the target's from the flange for
//    eye-to-hand);
//  - the camera starts 1000 mm from the target, pointing at it: nominal camera pose in the target
//    frame (OpenCV target frame, z into the board) at (0, 0, −d), optical axis +z toward the
//    target;
//  - stations: camera position uniform in a 1 m cube centred on the start point; orientation
//    = nominal · Rx(α) · Ry(β) · Rz(γ) with α, β ~ U(−45°, 45°) (axes parallel to the image
//    plane) and γ ~ U(−180°, 180°) (free about the optical axis); the target is assumed visible;
//  - the other unknown (Z) is a random pose: uniform rotation, translation U(−1, 1) m per axis;
//  - robot poses follow from the model Z = A_i X B_i (problem.h), then noise is added to the
//    robot poses T_base_gripper and the camera poses T_camera_target independently.
// Relative rotations between stations reach 180°, which is what breaks OpenCV 4.6's TSAI,
// HORAUD and DANIILIDIS.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"
#include "hecal/sim/noise.h"

namespace hecal::sim {

struct ProtocolOptions {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  int stations = 15;
  double start_distance = 1.0;           // metres, camera to target at the start
  double cube_side = 1.0;                // metres
  double max_tilt = 0.7853981633974483;  // radians (45°), about the image-plane axes
  double hand_eye_offset = 0.05;         // metres, |translation component| of the flange offset
  double other_offset = 1.0;             // metres, |translation component| of the other unknown

  // core/options_check.h: false naming ProtocolOptions.setup (not a Setup), .stations (below 1),
  // .start_distance (not above 0 and finite), .cube_side, .hand_eye_offset or .other_offset
  // (negative or not finite) or .max_tilt (not 0 … π/2: the camera would turn away from the
  // target).
  bool IsValid(std::string* why) const;
};

struct SimulatedData {
  handeye::Setup setup;
  Pose X;  // truth (problem.h meaning for the setup)
  Pose Z;  // truth
  std::vector<Pose> T_base_gripper_true;
  std::vector<Pose> T_camera_target_true;
  std::vector<Pose> T_base_gripper;   // measured (noisy)
  std::vector<Pose> T_camera_target;  // measured (noisy)

  handeye::Problem MeasuredProblem() const;
};

// The unknowns of one data set, drawn as above (uniform rotations; translations in the cube of the
// flange offset for the flange's unknown, of other_offset for the other).
struct HandEyeTruth {
  Pose X = Pose::Identity();
  Pose Z = Pose::Identity();
};
HandEyeTruth DrawTruth(const ProtocolOptions& options, std::mt19937_64& rng);

// T_target_camera at tilts alpha, beta about the image-plane axes and spin gamma about the optical
// axis, displaced by `displacement` from the start point (0, 0, −start_distance).
Pose CameraInTarget(const ProtocolOptions& options, double alpha, double beta, double gamma,
                    const Eigen::Vector3d& displacement);

// T_base_gripper that puts the camera at T_target_camera (from Z = A X B, problem.h).
Pose RobotPoseFor(handeye::Setup setup, const HandEyeTruth& truth, const Pose& T_target_camera);

// Throws hecal::InputError when !options.IsValid.
// The rng draws the truth, then the stations, then the noise (AddMeasurementNoise).
SimulatedData SimulateThesisProtocol(const ProtocolOptions& options, const NoiseModel& robot_noise,
                                     const NoiseModel& camera_noise, std::mt19937_64& rng);

// The measured poses from the true ones: per station, in order, the robot pose's noise and then
// the camera pose's, each T · Exp(δ) (noise.h). Replaces data->T_base_gripper and
// data->T_camera_target; a second call with a fresh rng redraws the noise on the same truth
// (a noise-only Monte Carlo over one geometry).
void AddMeasurementNoise(const NoiseModel& robot_noise, const NoiseModel& camera_noise,
                         std::mt19937_64& rng, SimulatedData* data);

}  // namespace hecal::sim
