#include "hecal/estimation/reprojection_refinement.h"

#include <ceres/crs_matrix.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/estimation/reprojection_cost.h"
#include "small_problem.h"

namespace hecal::estimation {
namespace {

using Parameters = std::array<double, kPoseAmbientSize>;

// Σ ‖r_k‖² of pixel residuals (px²).
double SquaredSum(const std::vector<Eigen::Vector2d>& residuals) {
  double sum = 0.0;
  for (const Eigen::Vector2d& r : residuals) sum += r.squaredNorm();
  return sum;
}

struct VarianceComponent {
  double squared_sum = 0.0;  // of the whitened residuals of the group
  double redundancy = 0.0;   // m_k − tr(N⁻¹ N_k)
};

// Smallest robot sigmas the estimate may reach (radians, metres): far below any real robot, and
// keeps the robot prior's weights within the solver's numerical range on noise-free data.
constexpr double kMinRobotSigma = 1e-7;

// The farthest a robot pose may be from the base (metres): far beyond any industrial robot or
// gantry, and far below the kilometres of millimetre lengths read as metres.
constexpr double kMaxRobotReach = 100.0;

// The fewest degrees of freedom PosteriorMeanFactor takes (E[σ] is infinite at ν ≤ 2).
constexpr double kMinPosteriorDof = 3.0;

// E[σ]² / σ̂² for a variance estimated with ν degrees of freedom under a prior flat in σ (header:
// "Covariance"): σ̂² ν / σ² ~ χ²(ν) gives an inverse-gamma posterior of σ², and
// E[σ]² = σ̂² (ν/2) (Γ(ν/2 − 1) / Γ((ν − 1)/2))² (1.16 at ν = 18, 1.04 at ν = 78, → 1). ν is
// clamped to at least kMinPosteriorDof, where the mean is finite.
double PosteriorMeanFactor(double dof) {
  const double nu = std::max(dof, kMinPosteriorDof);
  const double log_ratio = std::lgamma(0.5 * nu - 1.0) - std::lgamma(0.5 * (nu - 1.0));
  return 0.5 * nu * std::exp(2.0 * log_ratio);
}

Parameters ToParameters(const Pose& T) {
  Parameters p;
  PoseToParameters(T, p.data());
  return p;
}

void Validate(const std::vector<Pose>& T_base_gripper, const std::vector<ImagePoints>& images) {
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
}

// The start must be finite, at a robot's scale, and put every target point in front of its
// camera; otherwise the solver has nothing sound to start from (it would stop at once with a
// non-finite cost, or wander off).
void ValidateStart(const std::vector<Pose>& T_base_gripper, const std::vector<ImagePoints>& images,
                   const Pose& X0, const Pose& Z0, const ReprojectionOptions& options) {
  const auto finite = [](const Pose& T) { return T.matrix().allFinite(); };
  if (!finite(X0) || !finite(Z0)) {
    throw DegenerateError("the joint reprojection refinement: the start X, Z is not finite",
                          "check the robot poses and the camera poses of the images");
  }
  for (size_t i = 0; i < images.size(); ++i) {
    const Pose& G = T_base_gripper[i];
    if (!finite(G)) {
      throw InputError("robot poses", static_cast<int>(i + 1), "the robot pose is not finite",
                       "give finite numbers in the robot file");
    }
    if (G.translation().norm() > kMaxRobotReach) {
      throw DegenerateError("the joint reprojection refinement: robot pose " +
                                std::to_string(i + 1) + " is " +
                                std::to_string(static_cast<long>(G.translation().norm())) +
                                " m from the base, beyond any robot's reach",
                            "check the robot file's length unit (give --units mm for "
                            "millimetres)");
    }
    for (size_t k = 0; k < images[i].target.size(); ++k) {
      if (!images[i].target[k].allFinite() || !images[i].pixels[k].allFinite()) {
        throw InputError("image points", static_cast<int>(i + 1),
                         "a target point or pixel is not finite", "check the detections");
      }
    }
    const Pose B = CameraFromUnknowns(options.setup, X0, Z0, G);
    for (const Eigen::Vector3d& P : images[i].target) {
      if (!((B * P).z() > 0.0)) {
        throw DegenerateError(
            "the joint reprojection refinement: its start (the pose-level X and Z) puts the "
            "target behind the camera of image " +
                std::to_string(i + 1),
            "check that the robot poses pair with the images and that --setup and the length "
            "units are right");
      }
    }
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
        robot_sigma_(options.robot_sigma),
        x_(ToParameters(X0)),
        z_(ToParameters(Z0)),
        k_(pose::IntrinsicsOf(options.camera)) {
    for (const Pose& G : T_base_gripper) g_.push_back(ToParameters(G));
  }

  bool RobotFree() const { return robot_sigma_.rotation > 0.0 && robot_sigma_.translation > 0.0; }

  // Solves at pixel sigma `sigma`; returns the sum of squared pixel residuals (px²).
  double Solve(double sigma) {
    ceres::Problem problem(internal::SmallProblemOptions());
    Build(sigma, &problem);
    ceres::Solver::Options solver = internal::SmallSolverOptions();
    solver.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
    if (RobotFree()) {
      // Each image's residuals touch X, Z and its own robot pose only: eliminate the robot poses
      // (6×6 blocks) and solve the 12×12 Schur complement — 20× faster than the dense normal
      // equations of 12 + 6n unknowns on 28 images of 408 points.
      solver.linear_solver_type = ceres::DENSE_SCHUR;
      auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
      for (Parameters& g : g_) ordering->AddElementToGroup(g.data(), 0);
      ordering->AddElementToGroup(x_.data(), 1);
      ordering->AddElementToGroup(z_.data(), 1);
      ordering->AddElementToGroup(k_.data(), 1);
      solver.linear_solver_ordering = ordering;
    }
    ceres::Solver::Summary summary;
    ceres::Solve(solver, &problem, &summary);
    return PixelSquaredSum();
  }

  // The inverse Gauss–Newton information at pixel sigma `sigma`, over the unknowns in the order
  // X, Z, the intrinsics when refined, the robot poses when free (Build).
  Eigen::MatrixXd InverseInformation(double sigma) { return Linearize(sigma).inverse; }

  // Variance components at pixel sigma `sigma` and the current robot sigma (Förstner 1979;
  // Koch 1999 §3.6): for the pixel rows and the robot prior's rotation and translation rows,
  // the whitened squared residual sum and the redundancy m_k − tr(N⁻¹ N_k).
  std::array<VarianceComponent, 3> VarianceComponents(double sigma) {
    const Linearization linear = Linearize(sigma);
    std::array<VarianceComponent, 3> components{};
    const ceres::CRSMatrix& J = linear.jacobian;
    for (int r = 0; r < J.num_rows; ++r) {
      double leverage = 0.0;  // J_r N⁻¹ J_rᵀ
      for (int a = J.rows[r]; a < J.rows[r + 1]; ++a) {
        for (int b = J.rows[r]; b < J.rows[r + 1]; ++b) {
          leverage += J.values[a] * linear.inverse(J.cols[a], J.cols[b]) * J.values[b];
        }
      }
      VarianceComponent& component = components[linear.group[static_cast<size_t>(r)]];
      component.squared_sum +=
          linear.residuals[static_cast<size_t>(r)] * linear.residuals[static_cast<size_t>(r)];
      component.redundancy += 1.0 - leverage;
    }
    return components;
  }

  PoseSigma& robot_sigma() { return robot_sigma_; }

  Pose X() const { return PoseFromParameters(x_.data()); }
  Pose Z() const { return PoseFromParameters(z_.data()); }
  Pose G(size_t i) const { return PoseFromParameters(g_[i].data()); }
  pose::CameraModel Camera() const { return pose::WithIntrinsics(options_.camera, k_.data()); }

  // The pixel error π(B P_k) − u_k of every point of station i (px).
  std::vector<Eigen::Vector2d> StationResiduals(size_t i) const {
    const Pose B = CameraFromUnknowns(options_.setup, X(), Z(), G(i));
    const pose::CameraModel camera = Camera();
    std::vector<Eigen::Vector2d> residuals;
    residuals.reserve(images_[i].target.size());
    for (size_t k = 0; k < images_[i].target.size(); ++k) {
      residuals.push_back(pose::Project(camera, B * images_[i].target[k]) - images_[i].pixels[k]);
    }
    return residuals;
  }

 private:
  struct Linearization {
    ceres::CRSMatrix jacobian;      // whitened
    std::vector<double> residuals;  // whitened
    std::vector<int> group;         // per row: 0 pixel, 1 robot rotation, 2 robot translation
    Eigen::MatrixXd inverse;        // N⁻¹, N = JᵀJ over every unknown
  };

  Linearization Linearize(double sigma) {
    ceres::Problem problem(internal::SmallProblemOptions());
    Build(sigma, &problem);
    Linearization linear;
    ceres::Problem::EvaluateOptions evaluate;
    evaluate.parameter_blocks = blocks_;
    problem.Evaluate(evaluate, nullptr, &linear.residuals, nullptr, &linear.jacobian);
    const ceres::CRSMatrix& J = linear.jacobian;
    Eigen::MatrixXd information = Eigen::MatrixXd::Zero(J.num_cols, J.num_cols);
    for (int r = 0; r < J.num_rows; ++r) {
      for (int a = J.rows[r]; a < J.rows[r + 1]; ++a) {
        for (int b = J.rows[r]; b < J.rows[r + 1]; ++b) {
          information(J.cols[a], J.cols[b]) += J.values[a] * J.values[b];
        }
      }
    }
    linear.inverse = information.ldlt().solve(Eigen::MatrixXd::Identity(J.num_cols, J.num_cols));
    // Rows in the order Build adds the residual blocks: per station its pixels (2 rows each),
    // then its robot prior (3 rotation, 3 translation rows) when the robot poses are free.
    for (const ImagePoints& image : images_) {
      linear.group.insert(linear.group.end(), 2 * image.target.size(), 0);
      if (RobotFree()) linear.group.insert(linear.group.end(), {1, 1, 1, 2, 2, 2});
    }
    return linear;
  }

  // Blocks in the order of the information matrix: X, Z, the intrinsics when refined, the robot
  // poses when free (constant blocks have no columns).
  void Build(double sigma, ceres::Problem* problem) {
    for (double* block : {x_.data(), z_.data()}) {
      problem->AddParameterBlock(block, kPoseAmbientSize, &manifold_);
    }
    for (Parameters& g : g_) problem->AddParameterBlock(g.data(), kPoseAmbientSize, &manifold_);
    problem->AddParameterBlock(k_.data(), pose::kNumIntrinsics);
    if (!options_.refine_intrinsics) problem->SetParameterBlockConstant(k_.data());
    blocks_ = {x_.data(), z_.data()};
    if (options_.refine_intrinsics) blocks_.push_back(k_.data());
    if (RobotFree()) {
      for (Parameters& g : g_) blocks_.push_back(g.data());
    }
    for (size_t i = 0; i < images_.size(); ++i) {
      for (size_t k = 0; k < images_[i].target.size(); ++k) {
        problem->AddResidualBlock(
            new ReprojectionCost(options_.setup, options_.camera, images_[i].target[k],
                                 images_[i].pixels[k], sigma),
            nullptr, x_.data(), z_.data(), g_[i].data(), k_.data());
      }
      if (RobotFree()) {
        problem->AddResidualBlock(
            new RobotPosePriorCost(measured_[i], robot_sigma_.rotation, robot_sigma_.translation),
            nullptr, g_[i].data());
      } else {
        problem->SetParameterBlockConstant(g_[i].data());
      }
    }
  }

  double PixelSquaredSum() const {
    double sum = 0.0;
    for (size_t i = 0; i < images_.size(); ++i) sum += SquaredSum(StationResiduals(i));
    return sum;
  }

  const std::vector<Pose>& measured_;
  const std::vector<ImagePoints>& images_;
  const ReprojectionOptions& options_;
  PoseSigma robot_sigma_;
  Parameters x_;
  Parameters z_;
  std::vector<Parameters> g_;
  pose::IntrinsicParameters k_;
  std::vector<double*> blocks_;
  Se3RightManifold manifold_;
};

}  // namespace

namespace {

bool PixelSigmaInRange(double pixel_sigma, std::string_view field, const std::string& fix,
                       std::string* why) {
  if (pixel_sigma > 0.0 && pixel_sigma <= kMaxPixelSigma) return true;
  char got[32];
  std::snprintf(got, sizeof(got), "%g", pixel_sigma);
  return Invalid(why, field, std::string("must be above 0 to 100 px, got ") + got, fix);
}

constexpr const char* kPixelSigmaFix = "give the noise of one image coordinate in pixels, e.g. 0.5";

}  // namespace

bool PixelSigmaIsValid(double pixel_sigma, std::string_view field, std::string* why) {
  return PixelSigmaInRange(pixel_sigma, field, kPixelSigmaFix, why);
}

bool PixelSigmaIsValid(const std::optional<double>& pixel_sigma, std::string_view field,
                       std::string* why) {
  return !pixel_sigma ||
         PixelSigmaInRange(*pixel_sigma, field,
                           std::string(kPixelSigmaFix) + ", or leave it unset to estimate it", why);
}

bool ReprojectionOptions::IsValid(std::string* why) const {
  if (!(robot_sigma.rotation >= 0.0 && std::isfinite(robot_sigma.rotation) &&
        robot_sigma.translation >= 0.0 && std::isfinite(robot_sigma.translation))) {
    return Invalid(why, "ReprojectionOptions.robot_sigma", "sigmas must be finite and non-negative",
                   "give values >= 0 (radians, metres)");
  }
  if (!PixelSigmaIsValid(pixel_sigma, "ReprojectionOptions.pixel_sigma", why)) return false;
  if (max_sigma_iterations < 1) {
    return Invalid(why, "ReprojectionOptions.max_sigma_iterations",
                   "must be at least 1, got " + std::to_string(max_sigma_iterations),
                   "use e.g. 30");
  }
  return true;
}

ReprojectionResult RefineReprojection(const std::vector<Pose>& T_base_gripper,
                                      const std::vector<ImagePoints>& images, const Pose& X0,
                                      const Pose& Z0, const ReprojectionOptions& options) {
  RequireValid(options);
  Validate(T_base_gripper, images);
  ValidateStart(T_base_gripper, images, X0, Z0, options);
  Refinement refinement(T_base_gripper, images, X0, Z0, options);
  size_t points = 0;
  for (const ImagePoints& image : images) points += image.target.size();
  // The robot priors add 6n residuals for the 6n robot unknowns, so the pixel degrees of freedom
  // are 2m − 12 whether the robot poses are free or fixed.
  const double dof = 2.0 * static_cast<double>(points) - 12.0 -
                     (options.refine_intrinsics ? pose::kNumIntrinsics : 0.0);
  if (images.size() < 3 || dof < 1.0) {
    throw DegenerateError("X and Z from " + std::to_string(images.size()) + " image(s) with " +
                              std::to_string(points) + " detected point(s)",
                          "use at least 3 images in which the target is detected");
  }

  ReprojectionResult result;
  result.pixel_sigma_estimated = !options.pixel_sigma;
  result.robot_sigma_estimated = options.estimate_robot_sigma && refinement.RobotFree();
  double sigma = options.pixel_sigma.value_or(1.0);
  for (int iteration = 0; iteration < options.max_sigma_iterations; ++iteration) {
    const double squared = refinement.Solve(sigma);
    if (!result.pixel_sigma_estimated && !result.robot_sigma_estimated) break;
    if (!result.robot_sigma_estimated) {
      const double estimate = std::max(std::sqrt(squared / dof), 1e-12);
      const bool converged = std::abs(estimate - sigma) <= 1e-3 * sigma;
      sigma = estimate;
      if (converged) break;
      continue;
    }
    // Each group's variance scaled by its whitened squared sum over its redundancy.
    const std::array<VarianceComponent, 3> c = refinement.VarianceComponents(sigma);
    const auto scale = [](const VarianceComponent& component) {
      return component.redundancy > 0.5 ? std::sqrt(component.squared_sum / component.redundancy)
                                        : 1.0;
    };
    PoseSigma& robot = refinement.robot_sigma();
    const std::array<double, 3> factors = {result.pixel_sigma_estimated ? scale(c[0]) : 1.0,
                                           scale(c[1]), scale(c[2])};
    sigma = std::max(sigma * factors[0], 1e-12);
    robot.rotation = std::max(robot.rotation * factors[1], kMinRobotSigma);
    robot.translation = std::max(robot.translation * factors[2], kMinRobotSigma);
    if (std::all_of(factors.begin(), factors.end(),
                    [](double f) { return std::abs(f - 1.0) <= 1e-2; })) {
      refinement.Solve(sigma);
      break;
    }
  }
  result.robot_sigma = refinement.robot_sigma();
  result.pixel_sigma = sigma;
  result.X = refinement.X();
  result.Z = refinement.Z();
  // The covariance at the posterior-mean sigmas of the estimated groups (header: "Covariance").
  double covariance_sigma = sigma;
  if (result.robot_sigma_estimated) {
    const std::array<VarianceComponent, 3> c = refinement.VarianceComponents(sigma);
    if (result.pixel_sigma_estimated)
      covariance_sigma *= std::sqrt(PosteriorMeanFactor(c[0].redundancy));
    result.robot_sigma_covariance = {
        result.robot_sigma.rotation * std::sqrt(PosteriorMeanFactor(c[1].redundancy)),
        result.robot_sigma.translation * std::sqrt(PosteriorMeanFactor(c[2].redundancy))};
    refinement.robot_sigma() = result.robot_sigma_covariance;
  } else {
    result.robot_sigma_covariance = result.robot_sigma;
  }
  const Eigen::MatrixXd inverse = refinement.InverseInformation(covariance_sigma);
  result.covariance = inverse.topLeftCorner<12, 12>();
  result.camera = refinement.Camera();
  if (options.refine_intrinsics) {
    result.intrinsics_covariance =
        inverse.block<pose::kNumIntrinsics, pose::kNumIntrinsics>(12, 12);
  }
  double total = 0.0;
  for (size_t i = 0; i < images.size(); ++i) {
    result.T_base_gripper.push_back(refinement.G(i));
    result.residuals_px.push_back(refinement.StationResiduals(i));
    const double squared = SquaredSum(result.residuals_px.back());
    total += squared;
    const double n = std::max<double>(1.0, static_cast<double>(images[i].target.size()));
    result.image_rms_px.push_back(std::sqrt(squared / n));
    result.image_outlier.push_back(result.image_rms_px.back() > 3.0 * sigma);
  }
  result.rms_px = std::sqrt(total / std::max<double>(1.0, static_cast<double>(points)));
  if (!result.X.matrix().allFinite() || !result.Z.matrix().allFinite() ||
      !result.covariance.allFinite() || !std::isfinite(result.rms_px) ||
      !std::isfinite(result.pixel_sigma)) {
    throw DegenerateError("the joint reprojection refinement: the solution is not finite",
                          "check the intrinsics (a distortion coefficient far outside its usual "
                          "range?) and the robot poses");
  }
  return result;
}

}  // namespace hecal::estimation
