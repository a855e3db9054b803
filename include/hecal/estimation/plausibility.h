// Physical plausibility of a calibration: the mistakes that leave the fit consistent and the
// answer wrong. Both files in the same wrong unit scale X, Z and the residuals alike (the
// convention diagnosis, handeye/convention_diagnosis.h, cannot see it); data that fit no setup at
// all leave residuals far above any robot's or camera's noise. These checks turn such results
// into loud warnings naming the likely mistake; they never change the result.
//
//   robot positions  median |t(T_base_gripper)| above kMaxRobotReach (20 m: beyond any arm or
//                    gantry cell) or, when the robot file did not name its unit, below
//                    kMinLength (1 mm): millimetres read as metres, or the reverse.
//   camera distance  median |t(T_camera_target)| above kMaxTargetDistance (20 m: a target the
//                    camera could not resolve) or, unit not named, below kMinLength.
//   hand-mounted     the camera (eye-in-hand X) or target (eye-to-hand Z) more than
//                    kMaxHandOffset (2 m) from the flange.
//   residuals        rotation RMS above kMaxResidualRotation (10°) or translation RMS above
//                    kMaxResidualLength (0.25) × the camera-to-target distance: robots repeat
//                    to ~0.1 mm / 0.01° and PnP poses are good to ~1 mm / 0.1°, so such residuals
//                    mean the poses do not describe one rigid setup (pairing, a moved target,
//                    frames).
#pragma once

#include <string>
#include <vector>

#include "hecal/estimation/calibrate.h"
#include "hecal/handeye/problem.h"

namespace hecal::estimation {

inline constexpr double kMaxRobotReach = 20.0;                       // m
inline constexpr double kMaxTargetDistance = 20.0;                   // m
inline constexpr double kMinLength = 1e-3;                           // m
inline constexpr double kMaxHandOffset = 2.0;                        // m
inline constexpr double kMaxResidualRotation = 0.17453292519943295;  // rad (10°)
inline constexpr double kMaxResidualLength = 0.25;  // × the camera-to-target distance

struct PlausibilityInput {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  std::vector<Pose> T_base_gripper;   // as read, metres
  std::vector<Pose> T_camera_target;  // as read, metres
  bool robot_unit_named = true;       // false: unit from a flag or the default
  bool camera_unit_named = true;
};

// The warnings for `result` (empty when everything is plausible).
std::vector<std::string> PlausibilityWarnings(const PlausibilityInput& input,
                                              const CalibrationResult& result);

}  // namespace hecal::estimation
