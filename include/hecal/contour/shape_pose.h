// The job of `hecal contour pose` (docs/contour.md): the camera motion of one shape vector
// S = (tx, ty, M11 − 1, M22 − 1, M21, M12) through the contour paper's weak perspective
// (affine_pose.h, PoseFromShape), and, when Σ_S is given, its Unscented-Transform covariance and
// bias check (pose_uncertainty.h, UnscentedPose). Translation in the unit of Z0, angles in
// radians in the rotation form's order (PoseParameterNames).
//
// Errors: hecal::InputError when !options.IsValid; hecal::DegenerateError from PoseFromShape for
// a singular shape (det M ≤ 0).
#pragma once

#include <optional>
#include <string>

#include "hecal/contour/affine_pose.h"
#include "hecal/contour/pose_uncertainty.h"
#include "hecal/geometry/types.h"

namespace hecal::contour {

struct ShapePoseOptions {
  ContourCamera camera;
  RotationForm form = RotationForm::kZyx;
  // Σ_S; none: no covariance. Symmetric to 1e-9 of its largest entry (the mean of it and its
  // transpose is used) and positive semidefinite.
  std::optional<Matrix6d> shape_covariance;
  UnscentedPoseOptions unscented;

  // core/options_check.h: false naming the camera's field (ContourCamera::IsValid),
  // ShapePoseOptions.form (not a RotationForm), .shape_covariance (not finite, not symmetric, a
  // negative eigenvalue) or the field of unscented.IsValid (used only with a covariance).
  bool IsValid(std::string* why) const;
};

struct ShapePose {
  ContourPose pose;  // the pose of S
  // With a covariance: the UT over Σ_S (mean, covariance, bias per parameter).
  std::optional<ContourPoseUncertainty> uncertainty;
};

ShapePose EstimateShapePose(const Vector6d& shape, const ShapePoseOptions& options);

}  // namespace hecal::contour
