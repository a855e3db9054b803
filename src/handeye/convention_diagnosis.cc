#include "hecal/handeye/convention_diagnosis.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hecal/core/error.h"

namespace hecal::handeye {
namespace {

constexpr double kRotationFloor = 1e-9;     // radians
constexpr double kTranslationFloor = 1e-9;  // relative to the length scale
constexpr double kEquallyGood = 2.0;        // gains within this factor fit about equally

void ScaleTranslations(std::vector<Pose>* poses, double factor) {
  for (Pose& T : *poses) T.translation() *= factor;
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

// How far the median robot reach and camera-to-target distance are from 1 m, in decades.
double ScaleImplausibility(const PoseData& data) {
  const auto median_length = [](const std::vector<Pose>& poses) {
    std::vector<double> lengths;
    for (const Pose& T : poses) lengths.push_back(std::max(T.translation().norm(), 1e-12));
    const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
    std::nth_element(lengths.begin(), middle, lengths.end());
    return lengths.empty() ? 1.0 : *middle;
  };
  return std::abs(std::log10(median_length(data.T_base_gripper))) +
         std::abs(std::log10(median_length(data.T_camera_target)));
}

// How many times smaller the candidate's median residual is than the reference's: rotation, and
// translation relative to each one's own length scale (a change of unit scales both alike).
double RotationRatio(const ConventionFit& candidate, const ConventionFit& reference) {
  return std::max(reference.median_rotation, kRotationFloor) /
         std::max(candidate.median_rotation, kRotationFloor);
}

double TranslationRatio(const ConventionFit& candidate, const ConventionFit& reference) {
  return std::max(reference.median_translation / reference.length_scale, kTranslationFloor) /
         std::max(candidate.median_translation / candidate.length_scale, kTranslationFloor);
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
  const Problem problem =
      MakeProblem(applied.setup, applied.T_base_gripper, applied.T_camera_target);
  fit.length_scale = LengthScale(problem);
  try {
    const StationConsensus consensus = FindStationConsensus(problem, options);
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
  struct Candidate {
    size_t index;
    double gain;
  };
  std::vector<Candidate> candidates;
  for (Convention convention : conventions) {
    diagnosis.alternatives.push_back(FitConvention(data, convention, options));
    const ConventionFit& fit = diagnosis.alternatives.back();
    if (!FitsClearlyBetter(fit, diagnosis.given)) continue;
    const double gain = !diagnosis.given.solved ? 1.0
                                                : RotationRatio(fit, diagnosis.given) *
                                                      TranslationRatio(fit, diagnosis.given);
    candidates.push_back({diagnosis.alternatives.size() - 1, gain});
  }
  if (candidates.empty()) return diagnosis;
  // Alternatives that fit about equally well (e.g. the robot in metres, or the camera in
  // millimetres: only the ratio of the units shows in the fit) are told apart by the lengths
  // they imply: the one closest to the scale of a robot cell wins.
  double best_gain = 0.0;
  for (const Candidate& c : candidates) best_gain = std::max(best_gain, c.gain);
  double best_scale = std::numeric_limits<double>::infinity();
  for (const Candidate& c : candidates) {
    if (c.gain < best_gain / kEquallyGood) continue;
    const double scale =
        ScaleImplausibility(ApplyConvention(data, diagnosis.alternatives[c.index].convention));
    if (scale < best_scale) {
      best_scale = scale;
      diagnosis.better = diagnosis.alternatives[c.index];
    }
  }
  return diagnosis;
}

bool FitsClearlyBetter(const ConventionFit& candidate, const ConventionFit& reference) {
  if (!candidate.solved) return false;
  if (!reference.solved) return true;
  const double rotation_ratio = RotationRatio(candidate, reference);
  const double translation_ratio = TranslationRatio(candidate, reference);
  return std::max(rotation_ratio, translation_ratio) >= kClearlyBetter &&
         std::min(rotation_ratio, translation_ratio) >= 1.0 / kNotWorse;
}

bool RobotInversionReading(const ConventionFit& fit) {
  // fit.setup is the other setup; the robot-inversion reading keeps the given one, in which the
  // hand-mounted unknown is the other of X and Z.
  const bool given_in_hand = fit.setup == Setup::kEyeToHand;
  const Pose& hand = given_in_hand ? fit.solution.X : fit.solution.Z;
  const Pose& cell = given_in_hand ? fit.solution.Z : fit.solution.X;
  return hand.translation().norm() < cell.translation().norm();
}

std::string_view ConventionName(Convention convention) {
  switch (convention) {
    case Convention::kAsGiven:
      return "the data as given";
    case Convention::kOtherSetup:
      return "the other setup (or the robot or the camera poses inverted)";
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
