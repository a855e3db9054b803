// OpenCV 4.6's hand–eye functions as PEERS of hecal's solvers, on hecal's Problem data (for the
// bench, `hecal bench` and comparison tests only — the core libraries never link OpenCV,
// docs/architecture.md#layers). Nothing here fixes OpenCV; it calls it exactly as a user would.
//
// Method mapping (docs/bench.md):
//   cv::calibrateHandEye            CALIB_HAND_EYE_TSAI → tsai-lenz, _PARK → park-martin,
//                                   _HORAUD → horaud, _ANDREFF → andreff,
//                                   _DANIILIDIS → daniilidis
//   cv::calibrateRobotWorldHandEye  CALIB_ROBOT_WORLD_HAND_EYE_SHAH → shah, _LI → li
//
// Convention mapping. hecal's model for both setups is Z = A_i · X · B_i (handeye/problem.h),
// with B_i = T_camera_target_i and A_i = T_base_gripper_i (eye-in-hand) or T_base_gripper_i⁻¹
// (eye-to-hand).
//
// cv::calibrateHandEye solves T_base_target = gripper2base_i · cam2gripper · target2cam_i
// (its eye-in-hand model; ^bT_g ^gT_c ^cT_t constant). So, in terms of A_i, B_i:
//   gripper2base_i := A_i,  target2cam_i := B_i,  X = cam2gripper.
//   eye-in-hand:  gripper2base = T_base_gripper,       target2cam = T_camera_target,
//                 cam2gripper  = X = T_gripper_camera.
//   eye-to-hand:  gripper2base = T_base_gripper⁻¹ (the inverse robot pose, base2gripper, as the
//                 OpenCV docs prescribe for a fixed camera), target2cam = T_camera_target,
//                 cam2gripper  = X = T_base_camera ("cam2base").
//   Z (which OpenCV does not return) comes from handeye::EstimateZ, as for hecal's motion
//   solvers. OpenCV 4.6 forms the motions from ALL station pairs, as hecal does, but stacks them
//   into dense 3K×3 (TSAI, PARK/HORAUD translation), 12K×12 (ANDREFF) or 6K×8 (DANIILIDIS)
//   matrices, K = n(n−1)/2, solved by SVD — hence its cost at large n.
//
// cv::calibrateRobotWorldHandEye solves world2cam_i = gripper2cam · base2gripper_i · base2world
// (^cT_w = ^cT_g ^gT_b ^bT_w, world = the target). Substituting hecal's model,
// B_i = X⁻¹ · A_i⁻¹ · Z, so:
//   world2cam_i := B_i,  base2gripper_i := A_i⁻¹,  X = gripper2cam⁻¹,  Z = base2world⁻¹.
//   eye-in-hand:  world2cam = T_camera_target, base2gripper = T_base_gripper⁻¹ = T_gripper_base;
//                 gripper2cam = T_camera_gripper = X⁻¹, base2world = T_target_base = Z⁻¹.
//   eye-to-hand:  (OpenCV's "gripper" is our fixed base, its "base" our moving gripper)
//                 world2cam = T_camera_target, base2gripper = T_base_gripper;
//                 gripper2cam = T_camera_base = X⁻¹, base2world = T_target_gripper = Z⁻¹.
//
// OpenCV prints its own warnings and may return NaN (e.g. DANIILIDIS on wide rotations) or throw
// cv::Exception; SolveWithOpenCv returns what OpenCV returned (possibly non-finite) and lets
// cv::Exception through as std::runtime_error (cv::Exception derives from std::exception).
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/closed_form.h"
#include "hecal/handeye/problem.h"

namespace hecal::peers {

// True for the seven methods OpenCV 4.6 implements (mapping above).
bool HasOpenCvPeer(handeye::ClosedForm method);
// The methods with an OpenCV peer, in handeye::ClosedForms() order.
std::vector<handeye::ClosedForm> OpenCvPeerMethods();

// A Problem converted once to OpenCV's inputs (3×3 CV_64F rotations, 3×1 CV_64F translations),
// so a benchmark times OpenCV's solver rather than the conversion.
struct OpenCvInput {
  handeye::Problem problem;               // kept for EstimateZ
  std::vector<cv::Mat> R_A, t_A;          // A_i     (gripper2base for calibrateHandEye)
  std::vector<cv::Mat> R_B, t_B;          // B_i     (target2cam / world2cam)
  std::vector<cv::Mat> R_A_inv, t_A_inv;  // A_i⁻¹   (base2gripper for calibrateRobotWorldHandEye)
};

OpenCvInput PrepareOpenCvInput(const handeye::Problem& problem);

// Runs OpenCV's function for `method` (precondition: HasOpenCvPeer(method)) and maps the result
// back to hecal's X and Z. With estimate_z == false, calibrateHandEye's Z is left as identity
// (the bench times the solver only).
handeye::Solution SolveWithOpenCv(handeye::ClosedForm method, const OpenCvInput& input,
                                  bool estimate_z = true);
handeye::Solution SolveWithOpenCv(handeye::ClosedForm method, const handeye::Problem& problem);

}  // namespace hecal::peers
