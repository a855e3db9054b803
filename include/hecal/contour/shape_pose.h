// The job of `hecal contour pose` (docs/contour.md): the camera motion of one shape vector
// S = (tx, ty, M11 − 1, M22 − 1, M21, M12) through the contour paper's weak perspective
// (affine_pose.h, PoseFromShape), and, when Σ_S is given, its Unscented-Transform covariance and
// bias check (pose_uncertainty.h, UnscentedPose). Translation in the unit of Z0, angles in
// radians in the rotation form's order (PoseParameterNames).
//
// Errors: hecal::InputError for an invalid UT centre weight (the field `unscented`);
// hecal::DegenerateError from PoseFromShape for a singular shape (det M ≤ 0); those of
// ValidateContourCamera pass through.
#pragma once

#include <optional>

#include "hecal/contour/affine_pose.h"
#include "hecal/contour/pose_uncertainty.h"
#include "hecal/geometry/types.h"

namespace hecal::contour {

struct ShapePoseOptions {
  ContourCamera camera;
  RotationForm form = RotationForm::kZyx;
  std::optional<Matrix6d> shape_covariance;  // Σ_S; none: no covariance
  UnscentedPoseOptions unscented;
};

struct ShapePose {
  ContourPose pose;  // the pose of S
  // With a covariance: the UT over Σ_S (mean, covariance, bias per parameter).
  std::optional<ContourPoseUncertainty> uncertainty;
};

ShapePose EstimateShapePose(const Vector6d& shape, const ShapePoseOptions& options);

}  // namespace hecal::contour
