#include "hecal/estimation/plausibility.h"

#include <algorithm>
#include <cstdio>
#include <numbers>

namespace hecal::estimation {
namespace {

double MedianNorm(const std::vector<Pose>& poses) {
  if (poses.empty()) return 0.0;
  std::vector<double> norms;
  for (const Pose& T : poses) norms.push_back(T.translation().norm());
  const auto middle = norms.begin() + static_cast<std::ptrdiff_t>(norms.size() / 2);
  std::nth_element(norms.begin(), middle, norms.end());
  return *middle;
}

std::string Length(double metres) {
  char text[48];
  if (metres >= 1.0) {
    std::snprintf(text, sizeof text, "%.3g m", metres);
  } else {
    std::snprintf(text, sizeof text, "%.3g mm", metres * 1e3);
  }
  return text;
}

// The warning for a median distance outside [kMinLength, limit] (the low side only when the
// unit was not named), or empty.
std::string LengthWarning(const std::string& what, double median, double limit, bool named,
                          const std::string& file) {
  if (median > limit) {
    return what + " is " + Length(median) + " (median): implausible in metres — millimetres " +
           "read as metres? (name the unit of the " + file + " file: x_mm,y_mm,z_mm columns, or " +
           "--units mm)";
  }
  if (!named && median > 0.0 && median < kMinLength) {
    return what + " is " + Length(median) + " (median): implausibly small — metres read as " +
           "millimetres? (name the unit of the " + file + " file: x_m,y_m,z_m columns, or " +
           "leave out --units mm)";
  }
  return {};
}

}  // namespace

std::vector<std::string> PlausibilityWarnings(const PlausibilityInput& input,
                                              const CalibrationResult& result) {
  std::vector<std::string> warnings;
  const auto add = [&warnings](std::string warning) {
    if (!warning.empty()) warnings.push_back(std::move(warning));
  };
  add(LengthWarning("the robot flange's distance from the base", MedianNorm(input.T_base_gripper),
                    kMaxRobotReach, input.robot_unit_named, "robot"));
  const double distance = MedianNorm(input.T_camera_target);
  add(LengthWarning("the camera-to-target distance", distance, kMaxTargetDistance,
                    input.camera_unit_named, "camera"));
  const bool in_hand = input.setup == handeye::Setup::kEyeInHand;
  const double offset = (in_hand ? result.X : result.Z).translation().norm();
  if (offset > kMaxHandOffset) {
    add(std::string("the ") + (in_hand ? "camera" : "target") + " is " + Length(offset) +
        " from the robot flange (" + std::string(in_hand ? "X" : "Z") +
        "): implausible for a part mounted on the hand — check the units of both files, the "
        "setup and the pose directions");
  }
  const double rotation = result.rotation_rms * 180.0 / std::numbers::pi;
  if (result.rotation_rms > kMaxResidualRotation ||
      result.translation_rms > kMaxResidualLength * std::max(distance, kMinLength)) {
    char text[96];
    std::snprintf(text, sizeof text, "%.3g deg / ", rotation);
    add("the residuals (" + std::string(text) + Length(result.translation_rms) +
        " RMS) are far above what robots and cameras produce: the poses do not describe one "
        "rigid setup, and no other setup, pose direction or unit fits better — check that each "
        "robot row is paired with the camera pose taken at the same station (ids, order, time "
        "stamps), that the target and the camera mount did not move, and the frames of both "
        "files");
  }
  return warnings;
}

}  // namespace hecal::estimation
