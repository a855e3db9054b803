// Camera pose methods by name (see pose_method.h).
#include "hecal/pose/pose_method.h"

#include <array>
#include <sstream>
#include <stdexcept>

#include "hecal/core/options_check.h"

namespace hecal::pose {
namespace {

constexpr std::array<PoseMethodInfo, 3> kMethods = {{
    {PoseMethod::kLinear, "linear",
     "the linear method of docs/pose-from-points.md, then Levenberg-Marquardt on the reprojection "
     "error (6+ non-coplanar "
     "points)",
     true},
    {PoseMethod::kLinearRaw, "linear-raw",
     "the linear method of docs/pose-from-points.md alone, the paper's estimate (6+ non-coplanar "
     "points, no covariance)",
     false},
    {PoseMethod::kDlt, "dlt",
     "normalised DLT (6+ non-coplanar points) or homography (4+ coplanar), then "
     "Levenberg-Marquardt",
     true},
}};

}  // namespace

std::span<const PoseMethodInfo> PoseMethods() {
  return kMethods;
}

const PoseMethodInfo& Info(PoseMethod method) {
  for (const PoseMethodInfo& info : kMethods) {
    if (info.method == method) return info;
  }
  throw std::invalid_argument("unknown pose method");
}

std::optional<PoseMethod> ParsePoseMethod(std::string_view name) {
  for (const PoseMethodInfo& info : kMethods) {
    if (info.name == name) return info.method;
  }
  return std::nullopt;
}

bool PoseOptions::IsValid(std::string* why) const {
  return linear.IsValid(why) && dlt.IsValid(why) && refinement.IsValid(why);
}

PoseEstimate EstimatePose(PoseMethod method, const std::vector<Eigen::Vector3d>& object_points,
                          const std::vector<Eigen::Vector2d>& pixels, const CameraModel& camera,
                          const PoseOptions& options) {
  RequireValid(options);
  const PoseMethodInfo& info = Info(method);
  if (method == PoseMethod::kDlt) {
    return FinishPose(std::string(info.name),
                      DltPose(object_points, pixels, camera, options.dlt).T_camera_target,
                      info.refined, object_points, pixels, camera, options.refinement);
  }
  const LinearPoseResult seed = LinearPose(object_points, pixels, camera, options.linear);
  PoseEstimate estimate = FinishPose(std::string(info.name), seed.T_camera_target, info.refined,
                                     object_points, pixels, camera, options.refinement);
  if (seed.rotation_residual > kUnreliableRotationResidual) {
    std::ostringstream warning;
    warning.precision(2);
    warning << "the linear rotation estimate is far from a rotation (residual "
            << seed.rotation_residual << " > " << kUnreliableRotationResidual
            << "): its pose may be tens of degrees off"
            << (info.refined ? " and the refinement may have stopped in a local minimum" : "")
            << "; check the reprojection RMS and the point pairing, and compare with --method "
               "dlt";
    estimate.warnings.push_back(warning.str());
  }
  return estimate;
}

PoseEstimate FinishPose(std::string method, const Pose& start, bool refine,
                        const std::vector<Eigen::Vector3d>& object_points,
                        const std::vector<Eigen::Vector2d>& pixels, const CameraModel& camera,
                        const RefinementOptions& refinement) {
  PoseEstimate estimate;
  estimate.method = std::move(method);
  if (refine) {
    RefinementResult refined = RefinePose(start, object_points, pixels, camera, refinement);
    estimate.T_camera_target = refined.T_camera_target;
    estimate.residuals_px = std::move(refined.residuals_px);
    estimate.rms_px = refined.rms_px;
    estimate.covariance = refined.covariance;
    estimate.sigma_px = refined.sigma_px;
    estimate.sigma_source = refined.sigma_source;
  } else {
    estimate.T_camera_target = start;
    estimate.residuals_px = ReprojectionResiduals(start, object_points, pixels, camera);
    estimate.rms_px = RmsPx(estimate.residuals_px);
  }
  return estimate;
}

}  // namespace hecal::pose
