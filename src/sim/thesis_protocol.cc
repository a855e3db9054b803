#include "hecal/sim/thesis_protocol.h"

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "hecal/core/options_check.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/euler.h"
#include "hecal/geometry/so3.h"

namespace hecal::sim {
namespace {

// The draws of each function are made one at a time, last component first: the order in which
// GCC evaluated the arguments of the one-line forms these replace, so that a seed gives the same
// data sets as before, with any compiler.

Eigen::Matrix3d UniformRotation(std::mt19937_64& rng) {
  hecal::NormalDistribution normal;
  const double z = normal(rng);
  const double y = normal(rng);
  const double x = normal(rng);
  const double w = normal(rng);
  return Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
}

Eigen::Vector3d UniformBox(std::mt19937_64& rng, double half_side) {
  hecal::UniformRealDistribution uniform(-half_side, half_side);
  const double z = uniform(rng);
  const double y = uniform(rng);
  const double x = uniform(rng);
  return {x, y, z};
}

// Random pose with uniform rotation and translation in [−offset, offset]³.
Pose RandomPose(std::mt19937_64& rng, double offset) {
  const Eigen::Vector3d translation = UniformBox(rng, offset);
  return MakePose(UniformRotation(rng), translation);
}

}  // namespace

Pose CameraInTarget(const ProtocolOptions& options, double alpha, double beta, double gamma,
                    const Eigen::Vector3d& displacement) {
  const Eigen::Matrix3d R =
      ElementaryRotation(0, alpha) * ElementaryRotation(1, beta) * ElementaryRotation(2, gamma);
  return MakePose(R, Eigen::Vector3d(0.0, 0.0, -options.start_distance) + displacement);
}

HandEyeTruth DrawTruth(const ProtocolOptions& options, std::mt19937_64& rng) {
  // The flange offset is the small one: X for eye-in-hand (camera on the flange), Z for
  // eye-to-hand (target on the flange).
  HandEyeTruth truth;
  if (options.setup == handeye::Setup::kEyeInHand) {
    truth.X = RandomPose(rng, options.hand_eye_offset);
    truth.Z = RandomPose(rng, options.other_offset);
  } else {
    truth.X = RandomPose(rng, options.other_offset);
    truth.Z = RandomPose(rng, options.hand_eye_offset);
  }
  return truth;
}

Pose RobotPoseFor(handeye::Setup setup, const HandEyeTruth& truth, const Pose& T_target_camera) {
  const Pose A = truth.Z * T_target_camera * truth.X.inverse();  // from Z = A X B
  return setup == handeye::Setup::kEyeInHand ? A : A.inverse();
}

handeye::Problem SimulatedData::MeasuredProblem() const {
  return handeye::MakeProblem(setup, T_base_gripper, T_camera_target);
}

bool ProtocolOptions::IsValid(std::string* why) const {
  if (setup != handeye::Setup::kEyeInHand && setup != handeye::Setup::kEyeToHand) {
    return Invalid(why, "ProtocolOptions.setup", "is not a setup",
                   "use eye-in-hand or eye-to-hand");
  }
  if (stations < 1) {
    return Invalid(why, "ProtocolOptions.stations",
                   "must be at least 1, got " + std::to_string(stations),
                   "give the number of robot stations to simulate (default 15)");
  }
  if (!(start_distance > 0.0) || !std::isfinite(start_distance)) {
    return Invalid(why, "ProtocolOptions.start_distance", "must be a finite distance above 0",
                   "give the camera's distance to the target in metres (default 1)");
  }
  const std::pair<const char*, double> lengths[] = {
      {"ProtocolOptions.cube_side", cube_side},
      {"ProtocolOptions.hand_eye_offset", hand_eye_offset},
      {"ProtocolOptions.other_offset", other_offset}};
  for (const auto& [field, length] : lengths) {
    if (!(length >= 0.0) || !std::isfinite(length)) {
      return Invalid(why, field, "must be a finite length, 0 or more",
                     "give it in metres (the defaults are in thesis_protocol.h)");
    }
  }
  if (!(max_tilt >= 0.0 && max_tilt <= 0.5 * std::numbers::pi)) {
    return Invalid(why, "ProtocolOptions.max_tilt", "must be 0 … π/2 rad",
                   "give the largest tilt about the image-plane axes (default π/4)");
  }
  return true;
}

SimulatedData SimulateThesisProtocol(const ProtocolOptions& options, const NoiseModel& robot_noise,
                                     const NoiseModel& camera_noise, std::mt19937_64& rng) {
  RequireValid(options);
  SimulatedData data;
  data.setup = options.setup;
  const HandEyeTruth truth = DrawTruth(options, rng);
  data.X = truth.X;
  data.Z = truth.Z;
  // Each station: position in the cube around (0, 0, −d), tilted about the image-plane axes and
  // spun about the optical axis.
  hecal::UniformRealDistribution tilt(-options.max_tilt, options.max_tilt);
  hecal::UniformRealDistribution spin(-std::numbers::pi, std::numbers::pi);
  for (int i = 0; i < options.stations; ++i) {
    const double alpha = tilt(rng);
    const double beta = tilt(rng);
    const double gamma = spin(rng);
    const Pose T_target_camera =
        CameraInTarget(options, alpha, beta, gamma, UniformBox(rng, 0.5 * options.cube_side));
    data.T_base_gripper_true.push_back(RobotPoseFor(options.setup, truth, T_target_camera));
    data.T_camera_target_true.push_back(T_target_camera.inverse());
  }
  // Noise after the truth so the noise-free data are the same whatever the noise model.
  AddMeasurementNoise(robot_noise, camera_noise, rng, &data);
  return data;
}

void AddMeasurementNoise(const NoiseModel& robot_noise, const NoiseModel& camera_noise,
                         std::mt19937_64& rng, SimulatedData* data) {
  const size_t n = data->T_base_gripper_true.size();
  data->T_base_gripper.clear();
  data->T_camera_target.clear();
  for (size_t i = 0; i < n; ++i) {
    data->T_base_gripper.push_back(AddNoise(data->T_base_gripper_true[i], robot_noise, rng));
    data->T_camera_target.push_back(AddNoise(data->T_camera_target_true[i], camera_noise, rng));
  }
}

}  // namespace hecal::sim
