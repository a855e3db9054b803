// Simulated recordings (docs/streams.md): a robot stream and a camera stream of one continuous
// motion, on two clocks, with known X, Z and time offset — the ground truth of `hecal simulate
// --streams`, the stream tests and the offset study.
//
// The geometry is the thesis protocol's (thesis_protocol.h) made continuous: the camera moves
// about the start point (0, 0, −d) in front of the target, each of its position coordinates
//     p_k(t) = ½ · cube_side · (0.6 sin(2π f₁ t + φ₁) + 0.4 sin(2π f₂ t + φ₂)),
// its tilts α(t), β(t) the same with amplitude max_tilt and its spin γ(t) with amplitude π/2,
// every f drawn from U(0.3, 1) · max_frequency and every φ from U(0, 2π); X and Z as the protocol
// draws them. The robot stream samples T_base_gripper at robot_rate on the robot clock
// (t = 0 … duration); the camera stream samples T_camera_target at camera_rate, a camera sample
// stamped t (camera clock) being taken at true (robot-clock) time t + time_offset (the convention
// of streams/time_offset_search.h). Noise: the thesis protocol's models (noise.h), drawn
// independently for every sample of each stream.
// `perfectly_paired`: for comparison, the same camera samples paired with robot poses measured at
// exactly their time (the true pose at t + time_offset with the robot's noise drawn once more):
// the data a perfectly synchronised recording would have given.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/sim/noise.h"
#include "hecal/sim/thesis_protocol.h"

namespace hecal::sim {

struct StreamSimulationOptions {
  ProtocolOptions protocol;     // setup and geometry (its `stations` is not used)
  double duration = 60.0;       // seconds of robot stream
  double robot_rate = 50.0;     // Hz
  double camera_rate = 30.0;    // Hz
  double time_offset = 0.0;     // seconds (convention above)
  double max_frequency = 0.05;  // Hz, of the motion's sinusoids
  // core/options_check.h: false naming StreamSimulationOptions.<field> (duration, rates and
  // max_frequency not above 0 and finite, time_offset not finite or not below duration / 2) or a
  // ProtocolOptions field.
  bool IsValid(std::string* why) const;
};

struct SimulatedStreams {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  Pose X = Pose::Identity();  // truth (problem.h meaning for the setup)
  Pose Z = Pose::Identity();
  double time_offset = 0.0;
  std::vector<double> robot_stamps;    // robot clock
  std::vector<Pose> T_base_gripper;    // measured
  std::vector<double> camera_stamps;   // camera clock
  std::vector<Pose> T_camera_target;   // measured
  std::vector<Pose> perfectly_paired;  // T_base_gripper measured at each camera sample's time
};

// Throws hecal::InputError when !options.IsValid. The rng draws the truth, the motion, then the
// noise of the robot stream, the camera stream and the perfectly paired robot poses.
SimulatedStreams SimulateStreams(const StreamSimulationOptions& options,
                                 const NoiseModel& robot_noise, const NoiseModel& camera_noise,
                                 std::mt19937_64& rng);

}  // namespace hecal::sim
