// Levenberg–Marquardt on the reprojection error over SE(3) and the pose covariance (see
// pose_refinement.h).
#include "hecal/pose/pose_refinement.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/skew.h"
#include "hecal/pose/linear_pose.h"

namespace hecal::pose {
namespace {

constexpr std::size_t kMinRefinementPoints = 3;
// Initial damping μ, relative to diag(JᵀJ) (Marquardt's scaling, so dimensionless; Madsen et
// al. recommend 1e-6 … 1 depending on trust in the start; the starts here are closed forms).
constexpr double kInitialDamping = 1e-3;
// No step lowers the cost once μ exceeds this: the step is then below the rounding of the
// parameters.
constexpr double kMaxDamping = 1e16;
// JᵀJ counts as singular when its smallest eigenvalue is below this fraction of its largest.
constexpr double kSingularInformation = 1e-14;

// Residuals r (2N) and, when J is not null, the Jacobian ∂r/∂δ (2N × 6) at T. False when a point
// is not in front of the camera (its index in *behind).
bool Linearise(const Pose& T, const std::vector<Eigen::Vector3d>& object_points,
               const std::vector<Eigen::Vector2d>& pixels, const CameraModel& camera,
               Eigen::VectorXd* r, Eigen::MatrixXd* J, std::size_t* behind) {
  const Eigen::Matrix3d& R = T.linear();
  for (std::size_t k = 0; k < object_points.size(); ++k) {
    const Eigen::Vector3d p = T * object_points[k];
    if (!(p.z() > 0.0)) {
      *behind = k;
      return false;
    }
    const Eigen::Index row = 2 * static_cast<Eigen::Index>(k);
    Eigen::Matrix<double, 2, 3> J_pi;
    r->segment<2>(row) = Project(camera, p, J != nullptr ? &J_pi : nullptr) - pixels[k];
    if (J != nullptr) {
      const Eigen::Matrix<double, 2, 3> J_R = J_pi * R;
      J->block<2, 3>(row, 0) = -J_R * Skew(object_points[k]);
      J->block<2, 3>(row, 3) = J_R;
    }
  }
  return true;
}

void CheckInputs(const std::vector<Eigen::Vector3d>& object_points,
                 const std::vector<Eigen::Vector2d>& pixels, const RefinementOptions& options) {
  CheckCorrespondences(object_points, pixels);
  if (object_points.size() < kMinRefinementPoints) {
    throw InputError(
        "image points", 0,
        "pose refinement needs at least 3 points, got " + std::to_string(object_points.size()),
        "give more point correspondences");
  }
  RequireValid(options);
}

}  // namespace

bool RefinementOptions::IsValid(std::string* why) const {
  if (max_iterations < 1) {
    return Invalid(why, "RefinementOptions.max_iterations",
                   "must be at least 1, got " + std::to_string(max_iterations), "use e.g. 100");
  }
  if (!(relative_cost_tolerance >= 0.0)) {
    return Invalid(why, "RefinementOptions.relative_cost_tolerance", "must be non-negative",
                   "use e.g. 1e-14");
  }
  if (pixel_sigma.has_value() && !(*pixel_sigma > 0.0 && std::isfinite(*pixel_sigma))) {
    return Invalid(why, "RefinementOptions.pixel_sigma",
                   "the pixel sigma must be positive and finite",
                   "give the pixel noise in px, e.g. 0.5, or leave it unset to estimate it");
  }
  return true;
}

std::string_view SigmaSourceName(SigmaSource source) {
  return source == SigmaSource::kGiven ? "given" : "estimated";
}

std::vector<Eigen::Vector2d> ReprojectionResiduals(
    const Pose& T_camera_target, const std::vector<Eigen::Vector3d>& object_points,
    const std::vector<Eigen::Vector2d>& pixels, const CameraModel& camera) {
  CheckCorrespondences(object_points, pixels);
  Eigen::VectorXd r(2 * static_cast<Eigen::Index>(object_points.size()));
  std::size_t behind = 0;
  if (!Linearise(T_camera_target, object_points, pixels, camera, &r, nullptr, &behind)) {
    throw DegenerateError("the reprojection of point " + std::to_string(behind + 1) +
                              ": the pose puts it behind the camera",
                          "check that the image points belong to the object points, in order");
  }
  std::vector<Eigen::Vector2d> residuals(object_points.size());
  for (std::size_t k = 0; k < residuals.size(); ++k) {
    residuals[k] = r.segment<2>(2 * static_cast<Eigen::Index>(k));
  }
  return residuals;
}

double RmsPx(const std::vector<Eigen::Vector2d>& residuals) {
  if (residuals.empty()) return 0.0;
  double sum = 0.0;
  for (const Eigen::Vector2d& e : residuals) sum += e.squaredNorm();
  return std::sqrt(sum / static_cast<double>(residuals.size()));
}

RefinementResult RefinePose(const Pose& initial_T_camera_target,
                            const std::vector<Eigen::Vector3d>& object_points,
                            const std::vector<Eigen::Vector2d>& pixels, const CameraModel& camera,
                            const RefinementOptions& options) {
  CheckInputs(object_points, pixels, options);
  const Eigen::Index rows = 2 * static_cast<Eigen::Index>(object_points.size());
  if (!options.pixel_sigma.has_value() && rows <= 6) {
    throw DegenerateError("the pixel noise: 3 points leave no redundancy to estimate it from",
                          "give the pixel sigma (--pixel-sigma) or more points");
  }

  RefinementResult result;
  Pose T = initial_T_camera_target;
  Eigen::VectorXd r(rows), r_trial(rows);
  Eigen::MatrixXd J(rows, 6);
  std::size_t behind = 0;
  if (!Linearise(T, object_points, pixels, camera, &r, &J, &behind)) {
    throw DegenerateError("the camera pose: the starting pose puts point " +
                              std::to_string(behind + 1) + " behind the camera",
                          "check that the image points belong to the object points, in order");
  }
  double cost = 0.5 * r.squaredNorm();
  Matrix6d JtJ = J.transpose() * J;
  Vector6d gradient = J.transpose() * r;
  double mu = kInitialDamping;
  double nu = 2.0;

  while (result.iterations < options.max_iterations && cost > 0.0) {
    ++result.iterations;
    const Matrix6d damped = JtJ + mu * Matrix6d(JtJ.diagonal().asDiagonal());
    const Vector6d delta = -damped.ldlt().solve(gradient);
    // The damped model's decrease, ½ δᵀ(μ D δ − g): when it is within the tolerance, this is
    // the last step worth trying.
    const double predicted = 0.5 * delta.dot(mu * JtJ.diagonal().cwiseProduct(delta) - gradient);
    const bool last = !(predicted > options.relative_cost_tolerance * cost);
    const Pose T_trial = T * se3::Exp(delta);
    const bool valid = delta.allFinite() && Linearise(T_trial, object_points, pixels, camera,
                                                      &r_trial, nullptr, &behind);
    const double cost_trial = valid ? 0.5 * r_trial.squaredNorm() : cost;
    if (cost_trial < cost) {
      const double rho = (cost - cost_trial) / predicted;  // gain ratio
      const bool small = cost - cost_trial <= options.relative_cost_tolerance * cost;
      T = T_trial;
      cost = cost_trial;
      Linearise(T, object_points, pixels, camera, &r, &J, &behind);
      JtJ = J.transpose() * J;
      gradient = J.transpose() * r;
      mu *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3));
      nu = 2.0;
      if (small || last) {
        result.converged = true;
        break;
      }
    } else {
      mu *= nu;
      nu *= 2.0;
      if (last || mu > kMaxDamping) {
        result.converged = true;
        break;
      }
    }
  }
  if (cost == 0.0) result.converged = true;

  result.T_camera_target = T;
  result.residuals_px.resize(object_points.size());
  for (std::size_t k = 0; k < object_points.size(); ++k) {
    result.residuals_px[k] = r.segment<2>(2 * static_cast<Eigen::Index>(k));
  }
  result.rms_px = RmsPx(result.residuals_px);

  const Eigen::SelfAdjointEigenSolver<Matrix6d> information(JtJ);
  if (!(information.eigenvalues()(0) > kSingularInformation * information.eigenvalues()(5))) {
    throw DegenerateError(
        "the camera pose: the points do not determine all six degrees of "
        "freedom (the reprojection Jacobian is rank deficient)",
        "use points that span a plane or a volume, not a line");
  }
  if (options.pixel_sigma.has_value()) {
    result.sigma_px = *options.pixel_sigma;
    result.sigma_source = SigmaSource::kGiven;
  } else {
    result.sigma_px = std::sqrt(r.squaredNorm() / static_cast<double>(rows - 6));
    result.sigma_source = SigmaSource::kEstimated;
  }
  const Matrix6d inverse = information.eigenvectors() *
                           information.eigenvalues().cwiseInverse().asDiagonal() *
                           information.eigenvectors().transpose();
  result.covariance = result.sigma_px * result.sigma_px * inverse;
  return result;
}

}  // namespace hecal::pose
