// The job of `hecal contour pose`: see shape_pose.h.
#include "hecal/contour/shape_pose.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <string>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"

namespace hecal::contour {

bool ShapePoseOptions::IsValid(std::string* why) const {
  if (!camera.IsValid(why)) return false;
  if (form != RotationForm::kZyx && form != RotationForm::kZxz) {
    return Invalid(why, "ShapePoseOptions.form", "is not a rotation form",
                   "use zyx (roll–pitch–yaw, the contour paper's choice) or zxz");
  }
  if (!shape_covariance) return true;
  const Matrix6d& C = *shape_covariance;
  if (!C.allFinite()) {
    return Invalid(why, "ShapePoseOptions.shape_covariance", "Σ_S is not finite",
                   "give finite variances");
  }
  const double scale = C.cwiseAbs().maxCoeff();
  if (!((C - C.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * scale)) {
    return Invalid(why, "ShapePoseOptions.shape_covariance", "Σ_S is not symmetric",
                   "give a symmetric matrix");
  }
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eigen(0.5 * (C + C.transpose()));
  if (eigen.eigenvalues().minCoeff() < -1e-12 * std::max(scale, 1e-300)) {
    return Invalid(why, "ShapePoseOptions.shape_covariance", "Σ_S has a negative eigenvalue",
                   "give a positive semidefinite covariance");
  }
  return unscented.IsValid(why);
}

ShapePose EstimateShapePose(const Vector6d& shape, const ShapePoseOptions& options) {
  RequireValid(options);
  ShapePose result;
  result.pose = PoseFromShape(shape, options.camera, options.form);
  if (options.shape_covariance) {
    const Matrix6d& C = *options.shape_covariance;
    result.uncertainty = UnscentedPose(shape, 0.5 * (C + C.transpose()), options.camera,
                                       options.form, options.unscented);
  }
  return result;
}

}  // namespace hecal::contour
