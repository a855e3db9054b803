#include "hecal/handeye/convention_diagnosis.h"

#include <algorithm>

#include "hecal/core/error.h"

namespace hecal::handeye {
namespace {

constexpr double kRotationFloor = 1e-9;     // radians
constexpr double kTranslationFloor = 1e-9;  // × the length scale

void ScaleTranslations(std::vector<Pose>* poses, double factor) {
  for (Pose& T : *poses) T.translation() *= factor;
}

void InvertAll(std::vector<Pose>* poses) {
  for (Pose& T : *poses) T = T.inverse();
}

// The quaternion read as (w', x', y', z') holds the true components one place off: shifted left
// means the true (w, x, y, z) = (x', y', z', w') (w,x,y,z values under x,y,z,w names); shifted
// right means (z', w', x', y') (x,y,z,w values under w,x,y,z names).
void ShiftQuaternions(std::vector<Pose>* poses, bool left) {
  for (Pose& T : *poses) {
    const Eigen::Quaterniond q(T.linear());
    const Eigen::Quaterniond shifted = left ? Eigen::Quaterniond(q.x(), q.y(), q.z(), q.w())
                                            : Eigen::Quaterniond(q.z(), q.w(), q.x(), q.y());
    T.linear() = shifted.normalized().toRotationMatrix();
  }
}

Setup Other(Setup setup) {
  return setup == Setup::kEyeInHand ? Setup::kEyeToHand : Setup::kEyeInHand;
}

}  // namespace

PoseData ApplyConvention(const PoseData& data, Convention convention) {
  PoseData out = data;
  switch (convention) {
    case Convention::kAsGiven:
      break;
    case Convention::kOtherSetup:
      out.setup = Other(data.setup);
      break;
    case Convention::kCameraInverted:
      InvertAll(&out.T_camera_target);
      break;
    case Convention::kBothInverted:
      out.setup = Other(data.setup);
      InvertAll(&out.T_camera_target);
      break;
    case Convention::kRobotMillimetres:
      ScaleTranslations(&out.T_base_gripper, 1e-3);
      break;
    case Convention::kRobotMetres:
      ScaleTranslations(&out.T_base_gripper, 1e3);
      break;
    case Convention::kCameraMillimetres:
      ScaleTranslations(&out.T_camera_target, 1e-3);
      break;
    case Convention::kCameraMetres:
      ScaleTranslations(&out.T_camera_target, 1e3);
      break;
    case Convention::kRobotQuaternionShiftedLeft:
    case Convention::kRobotQuaternionShiftedRight:
      ShiftQuaternions(&out.T_base_gripper, convention == Convention::kRobotQuaternionShiftedLeft);
      break;
    case Convention::kCameraQuaternionShiftedLeft:
    case Convention::kCameraQuaternionShiftedRight:
      ShiftQuaternions(&out.T_camera_target,
                       convention == Convention::kCameraQuaternionShiftedLeft);
      break;
  }
  return out;
}

ConventionFit FitConvention(const PoseData& data, Convention convention,
                            const ConsensusOptions& options) {
  const PoseData applied = ApplyConvention(data, convention);
  ConventionFit fit;
  fit.convention = convention;
  fit.setup = applied.setup;
  try {
    const StationConsensus consensus = FindStationConsensus(
        MakeProblem(applied.setup, applied.T_base_gripper, applied.T_camera_target), options);
    fit.solved = true;
    fit.median_rotation = consensus.median_rotation;
    fit.median_translation = consensus.median_translation;
    fit.solution = consensus.solution;
  } catch (const DegenerateError&) {
    fit.solved = false;
  }
  return fit;
}

ConventionDiagnosis DiagnoseConventions(const PoseData& data, const ConsensusOptions& options) {
  std::vector<Convention> conventions = {Convention::kOtherSetup};
  if (!data.camera_from_images) {
    conventions.push_back(Convention::kCameraInverted);
    conventions.push_back(Convention::kBothInverted);
  }
  if (!data.robot_unit_named) {
    conventions.push_back(Convention::kRobotMillimetres);
    conventions.push_back(Convention::kRobotMetres);
  }
  if (!data.camera_unit_named && !data.camera_from_images) {
    conventions.push_back(Convention::kCameraMillimetres);
    conventions.push_back(Convention::kCameraMetres);
  }
  if (data.robot_quaternions) {
    conventions.push_back(Convention::kRobotQuaternionShiftedLeft);
    conventions.push_back(Convention::kRobotQuaternionShiftedRight);
  }
  if (data.camera_quaternions && !data.camera_from_images) {
    conventions.push_back(Convention::kCameraQuaternionShiftedLeft);
    conventions.push_back(Convention::kCameraQuaternionShiftedRight);
  }
  ConventionDiagnosis diagnosis;
  diagnosis.given = FitConvention(data, Convention::kAsGiven, options);
  const double L = LengthScale(MakeProblem(data.setup, data.T_base_gripper, data.T_camera_target));
  double best_gain = 0.0;
  for (Convention convention : conventions) {
    diagnosis.alternatives.push_back(FitConvention(data, convention, options));
    const ConventionFit& fit = diagnosis.alternatives.back();
    if (!FitsClearlyBetter(fit, diagnosis.given, L)) continue;
    const double gain =
        !diagnosis.given.solved
            ? 1.0
            : std::max(diagnosis.given.median_rotation, kRotationFloor) /
                  std::max(fit.median_rotation, kRotationFloor) *
                  std::max(diagnosis.given.median_translation, kTranslationFloor * L) /
                  std::max(fit.median_translation, kTranslationFloor * L);
    if (gain > best_gain) {
      best_gain = gain;
      diagnosis.better = fit;
    }
  }
  return diagnosis;
}

bool FitsClearlyBetter(const ConventionFit& candidate, const ConventionFit& reference,
                       double length_scale) {
  if (!candidate.solved) return false;
  if (!reference.solved) return true;
  const double rotation_ratio = std::max(reference.median_rotation, kRotationFloor) /
                                std::max(candidate.median_rotation, kRotationFloor);
  const double translation_floor = kTranslationFloor * length_scale;
  const double translation_ratio = std::max(reference.median_translation, translation_floor) /
                                   std::max(candidate.median_translation, translation_floor);
  return std::max(rotation_ratio, translation_ratio) >= kClearlyBetter &&
         std::min(rotation_ratio, translation_ratio) >= 1.0 / kNotWorse;
}

bool PreferOtherSetup(const ConventionFit& fit) {
  const Pose& hand = fit.setup == Setup::kEyeInHand ? fit.solution.X : fit.solution.Z;
  const Pose& cell = fit.setup == Setup::kEyeInHand ? fit.solution.Z : fit.solution.X;
  return hand.translation().norm() <= cell.translation().norm();
}

std::string_view ConventionName(Convention convention) {
  switch (convention) {
    case Convention::kAsGiven:
      return "the data as given";
    case Convention::kOtherSetup:
      return "the other setup (or the robot poses inverted)";
    case Convention::kCameraInverted:
      return "the camera poses inverted";
    case Convention::kBothInverted:
      return "the other setup (or the robot poses inverted) and the camera poses inverted";
    case Convention::kRobotMillimetres:
      return "the robot lengths in millimetres";
    case Convention::kRobotMetres:
      return "the robot lengths in metres";
    case Convention::kCameraMillimetres:
      return "the camera lengths in millimetres";
    case Convention::kCameraMetres:
      return "the camera lengths in metres";
    case Convention::kRobotQuaternionShiftedLeft:
      return "the robot quaternion columns holding w,x,y,z under x,y,z,w names";
    case Convention::kRobotQuaternionShiftedRight:
      return "the robot quaternion columns holding x,y,z,w under w,x,y,z names";
    case Convention::kCameraQuaternionShiftedLeft:
      return "the camera quaternion columns holding w,x,y,z under x,y,z,w names";
    case Convention::kCameraQuaternionShiftedRight:
      return "the camera quaternion columns holding x,y,z,w under w,x,y,z names";
  }
  return "";
}

}  // namespace hecal::handeye
