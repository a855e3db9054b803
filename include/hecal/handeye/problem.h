// The hand–eye problem in one form for both setups (docs/conventions.md).
//
// Every station i gives a robot pose T_base_gripper_i and a camera pose T_camera_target_i. Both
// setups are the same equation on absolute poses
//        Z = A_i · X · B_i        for every station i,
// with B_i = T_camera_target_i and
//   eye-in-hand  (camera on the robot): A_i = T_base_gripper_i,    X = T_gripper_camera,
//                                       Z = T_base_target
//   eye-to-hand  (camera fixed):        A_i = T_base_gripper_i⁻¹,  X = T_base_camera,
//                                       Z = T_gripper_target
// Solvers only see (A_i, B_i) and return (X, Z); MakeProblem does the setup-dependent inverse.
// Units: metres and radians.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/geometry/types.h"

namespace hecal::handeye {

enum class Setup { kEyeInHand, kEyeToHand };

// "eye-in-hand" | "eye-to-hand" (the CLI spelling); nullopt otherwise.
std::optional<Setup> ParseSetup(std::string_view text);
std::string_view SetupName(Setup setup);
// Frame names of the unknowns for result files: X is "T_gripper_camera" or "T_base_camera",
// Z is "T_base_target" or "T_gripper_target".
std::string_view XFrameName(Setup setup);
std::string_view ZFrameName(Setup setup);

struct Problem {
  Setup setup = Setup::kEyeInHand;
  std::vector<Pose> A;  // see above
  std::vector<Pose> B;  // T_camera_target_i
};

// Requires T_base_gripper.size() == T_camera_target.size() (precondition; the readers check it).
Problem MakeProblem(Setup setup, const std::vector<Pose>& T_base_gripper,
                    const std::vector<Pose>& T_camera_target);

// A solution of the problem.
struct Solution {
  Pose X = Pose::Identity();
  Pose Z = Pose::Identity();
};

// Characteristic length of the data set: RMS camera-to-target distance |t(B_i)| (≥ 1 mm). Used
// to compare rotations (rad) with translations (m).
double LengthScale(const Problem& problem);

// For motion-based solvers that estimate X only: the Z that best fits Z ≈ A_i X B_i — the
// chordal L2 mean (rotation: nearest rotation to the mean matrix; translation: mean).
Pose EstimateZ(const Problem& problem, const Pose& X);

}  // namespace hecal::handeye
