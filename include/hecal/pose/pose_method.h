// Camera pose from known points by name (`hecal pose --method NAME`): the Eigen-only methods of
// this module, with one result type that the OpenCV methods (vision/opencv_pnp.h, built with
// the vision layer) fill through FinishPose.
//
//   linear      the linear pose paper (linear_pose.h), then the reprojection refinement
//   (pose_refinement.h).
//               The default: the paper's method made maximum-likelihood, with a covariance.
//   linear-raw  the linear pose paper alone, exactly the paper's estimate (no refinement, no
//   covariance:
//               the first-order covariance describes the ML estimate, not this one).
//   dlt         the normalised DLT, or the homography for a planar target (dlt_pose.h), then
//               the refinement.
// Every method needs at least 6 non-coplanar points, except dlt on a planar target (4 or more
// coplanar points); the errors name the methods that accept the data.
//
// Result: T_camera_target (x_camera = T · P, the object points' length unit), the per-point
// residuals and their RMS (px) at that pose, and — for refined methods — the 6×6 right-
// perturbation covariance (rx, ry, rz, tx, ty, tz) with the σ it uses (given or estimated, see
// pose_refinement.h). Warnings: linear and linear-raw add one when the linear rotation estimate
// is far from a rotation (LinearPoseResult::rotation_residual > kUnreliableRotationResidual):
// the paper's pose may then be tens of degrees off, and the refinement may stop in a local
// minimum (seen in 1 of 200 six-point problems at 0.1 px: a 101° start, 47 px RMS after
// refinement); the warning says to check the RMS and to compare with dlt.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"
#include "hecal/pose/dlt_pose.h"
#include "hecal/pose/linear_pose.h"
#include "hecal/pose/pose_refinement.h"

namespace hecal::pose {

enum class PoseMethod { kLinear, kLinearRaw, kDlt };

struct PoseMethodInfo {
  PoseMethod method;
  std::string_view name;     // CLI name
  std::string_view summary;  // one line for --help
  bool refined;              // followed by the reprojection refinement (and has a covariance)
};

// Every method, in the order `hecal pose --help` lists them.
std::span<const PoseMethodInfo> PoseMethods();
const PoseMethodInfo& Info(PoseMethod method);
std::optional<PoseMethod> ParsePoseMethod(std::string_view name);

struct PoseOptions {
  LinearPoseOptions linear;
  DltPoseOptions dlt;
  RefinementOptions refinement;  // its pixel_sigma: given σ (px) for the covariance, or none

  // core/options_check.h: false naming the first bad field of linear, dlt or refinement.
  bool IsValid(std::string* why) const;
};

struct PoseEstimate {
  std::string method;  // the name it was asked for ("linear", "dlt", "ippe", ...)
  Pose T_camera_target = Pose::Identity();
  std::vector<Eigen::Vector2d> residuals_px;  // π(T P_k) − u_k
  double rms_px = 0.0;
  // Refined methods only (see above).
  std::optional<Matrix6d> covariance;
  double sigma_px = 0.0;
  SigmaSource sigma_source = SigmaSource::kEstimated;
  std::vector<std::string> warnings;  // one sentence each, with what to do
};

// Runs `method` on object points (target frame) and their pixels in `camera`.
PoseEstimate EstimatePose(PoseMethod method, const std::vector<Eigen::Vector3d>& object_points,
                          const std::vector<Eigen::Vector2d>& pixels, const CameraModel& camera,
                          const PoseOptions& options = {});

// The common end of every method, also for solvers outside this module: with `refine`, the
// reprojection refinement from `start` (pose, residuals, RMS, covariance); without, the residuals
// and RMS of `start` as it is (no covariance).
PoseEstimate FinishPose(std::string method, const Pose& start, bool refine,
                        const std::vector<Eigen::Vector3d>& object_points,
                        const std::vector<Eigen::Vector2d>& pixels, const CameraModel& camera,
                        const RefinementOptions& refinement = {});

}  // namespace hecal::pose
