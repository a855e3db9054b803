// The uncertainty of the contour camera motion: see pose_uncertainty.h.
#include "hecal/contour/pose_uncertainty.h"

#include <cmath>
#include <numbers>
#include <string>

#include "hecal/core/error.h"

namespace hecal::contour {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

double WrapSigned(double a) {  // into (−π, π]
  double w = std::remainder(a, kTwoPi);
  if (w <= -std::numbers::pi) w += kTwoPi;
  return w;
}

}  // namespace

Vector6d PoseParametersNear(const Vector6d& shape, const ContourCamera& camera, RotationForm form,
                            const Vector6d& reference) {
  return PoseParametersNear(
      shape, [&](const Vector6d& s) { return PoseFromShape(s, camera, form); }, form, reference);
}

Vector6d PoseParametersNear(const Vector6d& shape, const PoseOfShape& pose_of_shape,
                            RotationForm form, const Vector6d& reference) {
  Vector6d p = PoseParameters(pose_of_shape(shape));
  const std::array<bool, 6> circular = CircularParameters(form);
  for (int j = 0; j < 6; ++j) {
    if (circular[static_cast<size_t>(j)]) p(j) = reference(j) + WrapSigned(p(j) - reference(j));
  }
  return p;
}

Vector6d PoseDifference(const Vector6d& a, const Vector6d& b, RotationForm form) {
  Vector6d d = a - b;
  const std::array<bool, 6> circular = CircularParameters(form);
  for (int j = 0; j < 6; ++j) {
    if (circular[static_cast<size_t>(j)]) d(j) = WrapSigned(d(j));
  }
  return d;
}

bool UnscentedPoseOptions::IsValid(std::string* why) const {
  std::string problem;
  if (!unscented.IsValid(6, &problem)) {
    return Invalid(why, "UnscentedPoseOptions.unscented", problem, "give w0 < 1 (default 0)");
  }
  if (!(bias_threshold > 0.0) || !std::isfinite(bias_threshold)) {
    return Invalid(why, "UnscentedPoseOptions.bias_threshold", "must be a finite number above 0",
                   "give the bias in standard deviations that marks a parameter (default 0.25)");
  }
  return true;
}

ContourPoseUncertainty UnscentedPose(const Vector6d& shape, const Matrix6d& shape_covariance,
                                     const ContourCamera& camera, RotationForm form,
                                     const UnscentedPoseOptions& options) {
  return UnscentedPose(
      shape, shape_covariance, [&](const Vector6d& s) { return PoseFromShape(s, camera, form); },
      form, options);
}

ContourPoseUncertainty UnscentedPose(const Vector6d& shape, const Matrix6d& shape_covariance,
                                     const PoseOfShape& pose_of_shape, RotationForm form,
                                     const UnscentedPoseOptions& options) {
  RequireValid(options);
  ContourPoseUncertainty result;
  result.pose = pose_of_shape(shape);
  result.parameters = PoseParameters(result.pose);
  // One thread: f records its points in call order (the centre first, then ±c S_i).
  const auto f = [&](const Eigen::VectorXd& s) -> Eigen::VectorXd {
    const Vector6d p = PoseParametersNear(s, pose_of_shape, form, result.parameters);
    result.sigma_shapes.push_back(s);
    result.sigma_poses.push_back(p);
    return p;
  };
  // The pose of the shape itself exists (above): a failure now is a sigma point's, i.e. the
  // covariance spreads the shape beyond the region where it has a pose.
  const auto too_wide = [&](const std::string& why) {
    return DegenerateError(
        "the pose covariance: Σ_S is too large for the shape vector — a UT sigma point (the "
        "shape ± a scaled column of √Σ_S) " +
            why,
        "give Σ_S of the tracked shape (standard deviations well below |M − I| and the distance "
        "to det M = 0), or a smaller --ut-w0");
  };
  uncertainty::Moments<Eigen::VectorXd> moments;
  try {
    moments = uncertainty::UnscentedTransform<Eigen::VectorXd, Eigen::VectorXd>(
        f, Eigen::VectorXd(shape), Eigen::MatrixXd(shape_covariance), options.unscented, 1);
  } catch (const DegenerateError& error) {
    throw too_wide("has no pose (" + error.unobservable() + ")");
  }
  if (!moments.mean.allFinite() || !moments.covariance.allFinite()) {
    throw too_wide("gives a non-finite pose");
  }
  result.mean = moments.mean;
  result.covariance = moments.covariance;
  for (int j = 0; j < 6; ++j) {
    const double sd = std::sqrt(std::max(0.0, result.covariance(j, j)));
    const double gap = std::abs(result.mean(j) - result.parameters(j));
    const bool biased = gap > options.bias_threshold * sd && gap > 1e-12;
    result.biased[static_cast<size_t>(j)] = biased;
    result.any_biased = result.any_biased || biased;
  }
  return result;
}

uncertainty::MonteCarloMoments<Eigen::VectorXd> MonteCarloPose(
    const Vector6d& shape, const Matrix6d& shape_covariance, const ContourCamera& camera,
    RotationForm form, const uncertainty::MonteCarloOptions& options) {
  const Vector6d reference = PoseParameters(PoseFromShape(shape, camera, form));
  return uncertainty::MonteCarloTransform<Eigen::VectorXd, Eigen::VectorXd>(
      [&](const Eigen::VectorXd& s) -> Eigen::VectorXd {
        return PoseParametersNear(s, camera, form, reference);
      },
      Eigen::VectorXd(shape), Eigen::MatrixXd(shape_covariance), options);
}

}  // namespace hecal::contour
