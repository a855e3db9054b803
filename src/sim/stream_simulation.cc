// Simulated robot and camera streams: stream_simulation.h (docs/streams.md).
#include "hecal/sim/stream_simulation.h"

#include <array>
#include <cmath>
#include <numbers>

#include "hecal/core/options_check.h"
#include "hecal/core/random_draws.h"

namespace hecal::sim {
namespace {

// a · (0.6 sin(2π f₁ t + φ₁) + 0.4 sin(2π f₂ t + φ₂)).
struct Wave {
  double amplitude = 0.0;
  std::array<double, 2> frequency{};
  std::array<double, 2> phase{};
  double operator()(double t) const {
    constexpr double kTwoPi = 2.0 * std::numbers::pi;
    return amplitude * (0.6 * std::sin(kTwoPi * frequency[0] * t + phase[0]) +
                        0.4 * std::sin(kTwoPi * frequency[1] * t + phase[1]));
  }
};

Wave DrawWave(double amplitude, double max_frequency, std::mt19937_64& rng) {
  hecal::UniformRealDistribution frequency(0.3 * max_frequency, max_frequency);
  hecal::UniformRealDistribution phase(0.0, 2.0 * std::numbers::pi);
  Wave wave{.amplitude = amplitude};
  for (int k = 0; k < 2; ++k) {
    wave.frequency[k] = frequency(rng);
    wave.phase[k] = phase(rng);
  }
  return wave;
}

}  // namespace

bool StreamSimulationOptions::IsValid(std::string* why) const {
  const std::pair<const char*, double> positive[] = {
      {"StreamSimulationOptions.duration", duration},
      {"StreamSimulationOptions.robot_rate", robot_rate},
      {"StreamSimulationOptions.camera_rate", camera_rate},
      {"StreamSimulationOptions.max_frequency", max_frequency}};
  for (const auto& [field, value] : positive) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      return Invalid(why, field, "must be a finite number above 0",
                     "see stream_simulation.h for its meaning and default");
    }
  }
  if (!std::isfinite(time_offset) || !(std::abs(time_offset) < 0.5 * duration)) {
    return Invalid(why, "StreamSimulationOptions.time_offset",
                   "must be finite and shorter than half the duration",
                   "give the camera clock's offset in seconds (e.g. 0.03)");
  }
  return protocol.IsValid(why);
}

SimulatedStreams SimulateStreams(const StreamSimulationOptions& options,
                                 const NoiseModel& robot_noise, const NoiseModel& camera_noise,
                                 std::mt19937_64& rng) {
  RequireValid(options);
  const ProtocolOptions& protocol = options.protocol;
  SimulatedStreams out;
  out.setup = protocol.setup;
  out.time_offset = options.time_offset;
  const HandEyeTruth truth = DrawTruth(protocol, rng);
  out.X = truth.X;
  out.Z = truth.Z;
  const double half = 0.5 * protocol.cube_side;
  std::array<Wave, 6> waves;
  const std::array<double, 6> amplitudes = {
      half, half, half, protocol.max_tilt, protocol.max_tilt, 0.5 * std::numbers::pi};
  for (size_t k = 0; k < 6; ++k) waves[k] = DrawWave(amplitudes[k], options.max_frequency, rng);
  // The true robot pose at true (robot-clock) time t.
  const auto robot_at = [&](double t) {
    const Pose T_target_camera =
        CameraInTarget(protocol, waves[3](t), waves[4](t), waves[5](t),
                       Eigen::Vector3d(waves[0](t), waves[1](t), waves[2](t)));
    return std::pair{RobotPoseFor(protocol.setup, truth, T_target_camera),
                     T_target_camera.inverse()};
  };
  const auto robot_samples =
      static_cast<size_t>(std::floor(options.duration * options.robot_rate)) + 1;
  for (size_t k = 0; k < robot_samples; ++k) {
    const double t = static_cast<double>(k) / options.robot_rate;
    out.robot_stamps.push_back(t);
    out.T_base_gripper.push_back(AddNoise(robot_at(t).first, robot_noise, rng));
  }
  // Camera samples whose true time lies within the robot stream.
  std::vector<double> true_times;
  for (double t = std::max(0.0, options.time_offset); t <= options.duration;) {
    out.camera_stamps.push_back(t - options.time_offset);
    out.T_camera_target.push_back(AddNoise(robot_at(t).second, camera_noise, rng));
    true_times.push_back(t);
    t = std::max(0.0, options.time_offset) +
        static_cast<double>(true_times.size()) / options.camera_rate;
  }
  for (const double t : true_times)
    out.perfectly_paired.push_back(AddNoise(robot_at(t).first, robot_noise, rng));
  return out;
}

}  // namespace hecal::sim
