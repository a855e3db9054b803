// OpenCV's two hand–eye functions as hecal jobs (the Python module's `hecal.calibrateHandEye` and
// `hecal.calibrateRobotWorldHandEye`, docs/python.md): the same inputs and outputs as OpenCV 4.6's
// cv::calibrateHandEye and cv::calibrateRobotWorldHandEye, solved by estimation::Calibrate, and
// refusing with the reason where OpenCV 4.6 returns a wrong answer silently.
//
// Frames (OpenCV's names ↔ hecal's, handeye/problem.h, eye-in-hand):
//   calibrateHandEye:            R/t_gripper2base = T_base_gripper (A_i), R/t_target2cam =
//                                T_camera_target (B_i); the result R/t_cam2gripper = X =
//                                T_gripper_camera. (Eye-to-hand callers pass base2gripper as
//                                OpenCV documents; X is then T_base_camera — the same equation.)
//   calibrateRobotWorldHandEye:  R/t_world2cam = T_camera_world = B_i (world = target),
//                                R/t_base2gripper = T_gripper_base = A_i⁻¹; the results
//                                R/t_base2world = T_world_base = Z⁻¹ and R/t_gripper2cam =
//                                T_camera_gripper = X⁻¹.
// Units: translations in any one unit (the results are in that unit); rotations as 3×3 matrices
// or Rodrigues vectors (radians), as OpenCV takes them.
//
// Methods (OpenCV's integers ↔ estimation::Method): calibrateHandEye 0 TSAI → tsai-lenz, 1 PARK →
// park-martin, 2 HORAUD → horaud, 3 ANDREFF → andreff, 4 DANIILIDIS → daniilidis, and
// kDropInMl (hecal's own, the default) → ml; calibrateRobotWorldHandEye 0 SHAH → shah, 1 LI → li,
// kDropInMl → ml.
//
// What the drop-in computes (DropInCalibrateOptions): X and Z only — no covariance, no model
// check, no convention check, no residual report, and by default no outlier rejection (OpenCV
// rejects none, so both use the same stations). The closed forms are hecal's solvers after the
// observability check, exactly as estimation::Calibrate runs them. `ml` is hecal's maximum-
// likelihood refinement (estimation/ml.h) from its usual first start, with a plug-in noise model:
// the per-axis RMS of the residuals Log(Z⁻¹ A_i X B_i) at that start, split equally between robot
// and camera, given as the sigmas — one weighted refinement instead of estimation::Calibrate's
// REML alternation of pose and noise levels (about 200 times as long at 15 stations), so its X
// can differ from `hecal calibrate --method ml` within the noise. With reject_outliers,
// estimation::Calibrate runs (its station selection, then the method with its own noise
// estimate), still without covariance and model check.
//
// Errors: hecal::InputError with the argument's OpenCV name as the source (line 0) for: an unknown
// method (OpenCV 4.6 returns the identity), fewer than 3 poses, lists of different lengths, a
// non-finite value, a rotation matrix that is not a rotation (|RᵀR − I| > 1e-3 or det ≤ 0, as the
// pose files' reader; closer ones are projected to the nearest rotation; OpenCV takes any matrix). hecal::DegenerateError (estimation::Calibrate's observability check) when the
// data do not determine X, naming what cannot be observed (e.g. parallel rotation axes).
// Thread-safe: separate calls share nothing.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/methods.h"

namespace hecal::jobs {

// hecal's own method integer for the OpenCV drop-in: `ml`. Chosen far outside OpenCV's enums
// (0–4 for hand–eye, 0–1 for robot-world) so that no future OpenCV method collides with it.
inline constexpr int kDropInMl = 0x4845;  // 18501, "HE"

// One rotation as OpenCV takes it: a 3×3 matrix, or a Rodrigues vector (axis × angle, radians).
struct DropInRotation {
  Eigen::Matrix3d matrix = Eigen::Matrix3d::Identity();  // when !is_vector
  Eigen::Vector3d vector = Eigen::Vector3d::Zero();      // when is_vector
  bool is_vector = false;
};

// One list of poses as OpenCV takes it: rotations and translations, one per station, and the
// OpenCV argument names of the two lists (the sources of errors).
struct DropInPoses {
  std::vector<DropInRotation> R;
  std::vector<Eigen::Vector3d> t;
  std::string R_name;  // e.g. "R_gripper2base"
  std::string t_name;  // e.g. "t_gripper2base"
};

struct DropInCalibrateOptions {
  int method = kDropInMl;        // OpenCV's integer (see above) or kDropInMl
  bool reject_outliers = false;  // OpenCV rejects none
};

// A rigid transform as OpenCV returns it.
struct DropInTransform {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
};

// The method of calibrateHandEye's integer (robot_world false) or calibrateRobotWorldHandEye's
// (robot_world true); nullopt for any other integer.
std::optional<estimation::Method> DropInMethod(int method, bool robot_world);

// cv::calibrateHandEye: R/t_cam2gripper (X = T_gripper_camera) from gripper2base (T_base_gripper)
// and target2cam (T_camera_target). Throws as listed above.
DropInTransform CalibrateHandEyeDropIn(const DropInPoses& gripper2base,
                                       const DropInPoses& target2cam,
                                       const DropInCalibrateOptions& options);

struct RobotWorldDropIn {
  DropInTransform base2world;   // T_world_base
  DropInTransform gripper2cam;  // T_camera_gripper
};

// cv::calibrateRobotWorldHandEye from world2cam (T_camera_world) and base2gripper
// (T_gripper_base). Throws as listed above.
RobotWorldDropIn CalibrateRobotWorldHandEyeDropIn(const DropInPoses& world2cam,
                                                  const DropInPoses& base2gripper,
                                                  const DropInCalibrateOptions& options);

}  // namespace hecal::jobs
