#include "hecal/estimation/reprojection_refinement.h"

#include <ceres/crs_matrix.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "hecal/core/error.h"
#include "hecal/estimation/reprojection_cost.h"
#include "small_problem.h"

namespace hecal::estimation {
namespace {

using Parameters = std::array<double, kPoseAmbientSize>;

Parameters ToParameters(const Pose& T) {
  Parameters p;
  PoseToParameters(T, p.data());
  return p;
}

void Validate(const std::vector<Pose>& T_base_gripper, const std::vector<ImagePoints>& images,
              const ReprojectionOptions& options) {
  if (T_base_gripper.size() != images.size()) {
    throw InputError("stations", 0,
                     std::to_string(T_base_gripper.size()) + " robot poses but " +
                         std::to_string(images.size()) + " images",
                     "give one robot pose per image");
  }
  for (const ImagePoints& image : images) {
    if (image.target.size() != image.pixels.size()) {
      throw InputError("image points", 0, "target points and pixels differ in number",
                       "pair every detected pixel with its target point");
    }
  }
  const PoseSigma& robot = options.robot_sigma;
  if (!std::isfinite(robot.rotation) || !std::isfinite(robot.translation) || robot.rotation < 0.0 ||
      robot.translation < 0.0) {
    throw InputError("--robot-sigma", 0, "sigmas must be finite and non-negative",
                     "give e.g. --robot-sigma 0.1,0.05 (mm, deg)");
  }
  if (options.pixel_sigma && !(*options.pixel_sigma > 0.0 && std::isfinite(*options.pixel_sigma))) {
    throw InputError("--pixel-sigma", 0, "the pixel sigma must be positive",
                     "give e.g. --pixel-sigma 0.3, or omit it to estimate it");
  }
}

// One Ceres problem over X, Z and the robot poses at pixel sigma `sigma`.
class Refinement {
 public:
  Refinement(const std::vector<Pose>& T_base_gripper, const std::vector<ImagePoints>& images,
             const Pose& X0, const Pose& Z0, const ReprojectionOptions& options)
      : measured_(T_base_gripper),
        images_(images),
        options_(options),
        x_(ToParameters(X0)),
        z_(ToParameters(Z0)) {
    for (const Pose& G : T_base_gripper) g_.push_back(ToParameters(G));
  }

  bool RobotFree() const {
    return options_.robot_sigma.rotation > 0.0 && options_.robot_sigma.translation > 0.0;
  }

  // Solves at pixel sigma `sigma`; returns the sum of squared pixel residuals (px²).
  double Solve(double sigma) {
    ceres::Problem problem(internal::SmallProblemOptions());
    Build(sigma, &problem);
    ceres::Solver::Options solver = internal::SmallSolverOptions();
    solver.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
    ceres::Solver::Summary summary;
    ceres::Solve(solver, &problem, &summary);
    return PixelSquaredSum();
  }

  // (X, Z) block of the inverse Gauss–Newton information at pixel sigma `sigma`.
  Eigen::Matrix<double, 12, 12> Covariance(double sigma) {
    ceres::Problem problem(internal::SmallProblemOptions());
    Build(sigma, &problem);
    ceres::CRSMatrix crs;
    ceres::Problem::EvaluateOptions evaluate;
    evaluate.parameter_blocks = blocks_;
    problem.Evaluate(evaluate, nullptr, nullptr, nullptr, &crs);
    Eigen::MatrixXd information = Eigen::MatrixXd::Zero(crs.num_cols, crs.num_cols);
    for (int r = 0; r < crs.num_rows; ++r) {
      for (int a = crs.rows[r]; a < crs.rows[r + 1]; ++a) {
        for (int b = crs.rows[r]; b < crs.rows[r + 1]; ++b) {
          information(crs.cols[a], crs.cols[b]) += crs.values[a] * crs.values[b];
        }
      }
    }
    const Eigen::MatrixXd inverse =
        information.ldlt().solve(Eigen::MatrixXd::Identity(crs.num_cols, crs.num_cols));
    return inverse.topLeftCorner<12, 12>();
  }

  Pose X() const { return PoseFromParameters(x_.data()); }
  Pose Z() const { return PoseFromParameters(z_.data()); }
  Pose G(size_t i) const { return PoseFromParameters(g_[i].data()); }

  // Squared pixel error of every point of station i, summed (px²), and the point count.
  double StationSquaredSum(size_t i) const {
    const Pose B = CameraFromUnknowns(options_.setup, X(), Z(), G(i));
    double sum = 0.0;
    for (size_t k = 0; k < images_[i].target.size(); ++k) {
      sum += (pose::Project(options_.camera, B * images_[i].target[k]) - images_[i].pixels[k])
                 .squaredNorm();
    }
    return sum;
  }

 private:
  void Build(double sigma, ceres::Problem* problem) {
    blocks_ = {x_.data(), z_.data()};
    for (Parameters& g : g_) blocks_.push_back(g.data());
    for (double* block : blocks_) problem->AddParameterBlock(block, kPoseAmbientSize, &manifold_);
    for (size_t i = 0; i < images_.size(); ++i) {
      for (size_t k = 0; k < images_[i].target.size(); ++k) {
        problem->AddResidualBlock(
            new ReprojectionCost(options_.setup, options_.camera, images_[i].target[k],
                                 images_[i].pixels[k], sigma),
            nullptr, x_.data(), z_.data(), g_[i].data());
      }
      if (RobotFree()) {
        problem->AddResidualBlock(
            new RobotPosePriorCost(measured_[i], options_.robot_sigma.rotation,
                                   options_.robot_sigma.translation),
            nullptr, g_[i].data());
      } else {
        problem->SetParameterBlockConstant(g_[i].data());
      }
    }
    if (!RobotFree()) blocks_.resize(2);  // constant blocks have no columns
  }

  double PixelSquaredSum() const {
    double sum = 0.0;
    for (size_t i = 0; i < images_.size(); ++i) sum += StationSquaredSum(i);
    return sum;
  }

  const std::vector<Pose>& measured_;
  const std::vector<ImagePoints>& images_;
  const ReprojectionOptions& options_;
  Parameters x_;
  Parameters z_;
  std::vector<Parameters> g_;
  std::vector<double*> blocks_;
  Se3RightManifold manifold_;
};

}  // namespace

ReprojectionResult RefineReprojection(const std::vector<Pose>& T_base_gripper,
                                      const std::vector<ImagePoints>& images, const Pose& X0,
                                      const Pose& Z0, const ReprojectionOptions& options) {
  Validate(T_base_gripper, images, options);
  Refinement refinement(T_base_gripper, images, X0, Z0, options);
  size_t points = 0;
  for (const ImagePoints& image : images) points += image.target.size();
  // The robot priors add 6n residuals for the 6n robot unknowns, so the pixel degrees of freedom
  // are 2m − 12 whether the robot poses are free or fixed.
  const double dof = 2.0 * static_cast<double>(points) - 12.0;
  if (images.size() < 3 || dof < 1.0) {
    throw DegenerateError("X and Z from " + std::to_string(images.size()) + " image(s) with " +
                              std::to_string(points) + " detected point(s)",
                          "use at least 3 images in which the target is detected");
  }

  ReprojectionResult result;
  result.pixel_sigma_estimated = !options.pixel_sigma;
  double sigma = options.pixel_sigma.value_or(1.0);
  for (int iteration = 0; iteration < options.max_sigma_iterations; ++iteration) {
    const double squared = refinement.Solve(sigma);
    if (options.pixel_sigma) break;
    const double estimate = std::max(std::sqrt(squared / dof), 1e-12);
    const bool converged = std::abs(estimate - sigma) <= 1e-3 * sigma;
    sigma = estimate;
    if (converged) break;
  }
  result.pixel_sigma = sigma;
  result.X = refinement.X();
  result.Z = refinement.Z();
  result.covariance = refinement.Covariance(sigma);
  double total = 0.0;
  for (size_t i = 0; i < images.size(); ++i) {
    result.T_base_gripper.push_back(refinement.G(i));
    const double squared = refinement.StationSquaredSum(i);
    total += squared;
    const double n = std::max<double>(1.0, static_cast<double>(images[i].target.size()));
    result.image_rms_px.push_back(std::sqrt(squared / n));
    result.image_outlier.push_back(result.image_rms_px.back() > 3.0 * sigma);
  }
  result.rms_px = std::sqrt(total / std::max<double>(1.0, static_cast<double>(points)));
  return result;
}

}  // namespace hecal::estimation
