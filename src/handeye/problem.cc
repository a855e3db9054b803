#include "hecal/handeye/problem.h"

#include <algorithm>
#include <cmath>

#include "hecal/geometry/nearest_rotation.h"

namespace hecal::handeye {

std::optional<Setup> ParseSetup(std::string_view text) {
  if (text == "eye-in-hand") return Setup::kEyeInHand;
  if (text == "eye-to-hand") return Setup::kEyeToHand;
  return std::nullopt;
}

std::string_view SetupName(Setup setup) {
  return setup == Setup::kEyeInHand ? "eye-in-hand" : "eye-to-hand";
}

std::string_view XFrameName(Setup setup) {
  return setup == Setup::kEyeInHand ? "T_gripper_camera" : "T_base_camera";
}

std::string_view ZFrameName(Setup setup) {
  return setup == Setup::kEyeInHand ? "T_base_target" : "T_gripper_target";
}

Problem MakeProblem(Setup setup, const std::vector<Pose>& T_base_gripper,
                    const std::vector<Pose>& T_camera_target) {
  Problem problem;
  problem.setup = setup;
  problem.B = T_camera_target;
  problem.A.reserve(T_base_gripper.size());
  for (const Pose& T : T_base_gripper) {
    problem.A.push_back(setup == Setup::kEyeInHand ? T : T.inverse());
  }
  return problem;
}

double LengthScale(const Problem& problem) {
  double sum = 0.0;
  for (const Pose& B : problem.B) sum += B.translation().squaredNorm();
  const double rms =
      problem.B.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(problem.B.size()));
  return std::max(rms, 1e-3);
}

Pose EstimateZ(const Problem& problem, const Pose& X) {
  Eigen::Matrix3d rotation_sum = Eigen::Matrix3d::Zero();
  Eigen::Vector3d translation_sum = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < problem.A.size(); ++i) {
    const Pose Z_i = problem.A[i] * X * problem.B[i];
    rotation_sum += Z_i.linear();
    translation_sum += Z_i.translation();
  }
  const double n = static_cast<double>(problem.A.size());
  return MakePose(NearestRotationSvd(rotation_sum / n), translation_sum / n);
}

}  // namespace hecal::handeye
