// Joint refinement of the reprojection error over X, Z and the robot poses: the image-level
// maximum-likelihood estimate, which `hecal calibrate --images` runs after the pose-level `ml`
// (ml.h) has given X and Z.
//
// Model (reprojection_cost.h): station i has a measured robot pose G̃_i = T_base_gripper_i and the
// detected pixels u_ik of target points P_k. Unknowns: X, Z and the true robot poses G_i.
//        minimise  Σ_ik ‖(π(B_i(X, Z, G_i) · P_k) − u_ik) / σ_px‖²
//                + Σ_i ‖W_robot · Log(G̃_i⁻¹ G_i)‖²
// i.e. the pixels are measurements with isotropic noise σ_px and the robot poses are noisy
// measurements with the right-perturbation noise model of --robot-sigma (W_robot =
// diag(1/σ_rot, 1/σ_trans)). When the robot sigma is zero in rotation or translation the robot
// poses are held fixed (treated as exact). The camera model (intrinsics, distortion) is fixed, or
// refined with X and Z (refine_intrinsics: 9 more unknowns; the covariance of X and Z then
// includes the intrinsics' uncertainty). Solved with Ceres (Levenberg–Marquardt,
// dense Schur complement: the robot poses eliminated, 12 unknowns left (21 with the intrinsics);
// with the robot fixed, dense normal Cholesky) on Se3RightManifold blocks.
//
// Pixel noise: --pixel-sigma when given; otherwise estimated from the residuals as
// σ̂² = Σ ‖π(B_i P_k) − u_ik‖² / (2m − 12 [− 9 with the intrinsics]) over the m points (the robot
// priors bring as many residuals as robot unknowns), alternated with the estimate until it changes
// by less than 1e-3 (relative) — only the pixel term is rescaled, the robot prior keeps its given
// weight.
//
// Robot noise (estimate_robot_sigma): the pixel, robot-rotation and robot-translation
// variances are estimated together as variance components (Förstner 1979; Koch, "Parameter
// Estimation and Hypothesis Testing in Linear Models", 1999, §3.6): each group's variance is
// multiplied by (its whitened squared residual sum) / (its redundancy m_k − tr(N⁻¹ N_k)), N the
// Gauss–Newton information over all unknowns and N_k its part from the group's rows, re-solving in
// between, until every factor is within 1e-2 of 1 (the estimates' own sampling error is several
// times larger: ≈ 1/√(2·redundancy), 11% for the robot sigmas of 28 stations). Unlike the
// pose-level estimate, this sees each image's true (anisotropic, correlated) pose uncertainty
// through its pixels.
//
// Covariance of (X, Z): the (X, Z) block of the Gauss–Newton inverse
// information over all unknowns (the robot poses marginalised), right perturbations, (ω, v) order,
// metres/radians. When the robot noise is estimated, the information is taken at the posterior-
// mean sigmas of the estimated groups, not at their point estimates: each group's σ̂² times
// E[σ]²/σ̂² = (ν/2) (Γ(ν/2 − 1) / Γ((ν − 1)/2))², ν its redundancy (the inverse-gamma posterior of
// a variance under a prior flat in σ, the rule of the pose level, noise_estimation.h "Posterior
// mean", in closed form). Why: the covariance of X must carry the sampling error of the
// estimated noise. With 8 stations each robot group rests on ν ≈ 3n − 6 = 18 degrees of freedom,
// and a covariance that takes σ̂² as known makes the NEES of X about 6·F(6, ν) instead of χ²(6):
// expected 2σ coverage 90.0% and 1σ 63% at ν = 18 (measured on 100 rendered 8-image sets: 88.0%
// and 71.0%; with the posterior means 92.0% and 79.0%, docs/uncertainty.md). The factor is 1.16 at
// ν = 18, 1.04 at 28 stations (ν = 78), ≈ 1 for the pixel sigma (thousands of residuals). X and Z
// are the solution at the point estimates, and robot_sigma reports the point estimate (median
// ratio to the truth 0.93 / 0.99 there; the posterior mean sits ≈ 8% above it at 8 stations).
//
// Per-image report: reprojection RMS (px) of each station; a station is flagged
// when its RMS exceeds 3 σ̂_px (a detection or robot-pose problem).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/estimation/pose_sigma.h"
#include "hecal/geometry/types.h"
#include "hecal/handeye/problem.h"
#include "hecal/pose/camera_model.h"

namespace hecal::estimation {

// The detected points of one station's image.
struct ImagePoints {
  std::vector<Eigen::Vector3d> target;  // P_k, target frame, metres
  std::vector<Eigen::Vector2d> pixels;  // u_k, pixels (same order)
};

// The largest pixel noise σ taken as a measurement's (px): above it the detections are not
// measurements of the target.
inline constexpr double kMaxPixelSigma = 100.0;

// core/options_check.h's check of a pixel sigma: it must be in (0, kMaxPixelSigma]; false naming
// `field` otherwise.
bool PixelSigmaIsValid(double pixel_sigma, std::string_view field, std::string* why);

// The same for an optional one (unset: estimated): given, it must be in (0, kMaxPixelSigma].
bool PixelSigmaIsValid(const std::optional<double>& pixel_sigma, std::string_view field,
                       std::string* why);

struct ReprojectionOptions {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  pose::CameraModel camera;
  PoseSigma robot_sigma;              // per axis; zero rotation or translation: robot held fixed
  std::optional<double> pixel_sigma;  // px; estimated when absent
  // Estimate the robot sigma (rotation and translation) with the pixel sigma, robot_sigma being
  // the starting value; needs robot_sigma > 0 in both (free robot poses).
  bool estimate_robot_sigma = false;
  // Refine the intrinsics (pose::IntrinsicsOf: fx, fy, cx, cy, k1, k2, p1, p2, k3) with X and Z,
  // `camera` being the starting value.
  bool refine_intrinsics = false;
  int max_sigma_iterations = 30;  // at least 1

  // core/options_check.h: false naming ReprojectionOptions.robot_sigma (negative or not finite),
  // .pixel_sigma (PixelSigmaIsValid) or .max_sigma_iterations (below 1).
  bool IsValid(std::string* why) const;
};

struct ReprojectionResult {
  Pose X = Pose::Identity();
  Pose Z = Pose::Identity();
  Eigen::Matrix<double, 12, 12> covariance;  // (δX, δZ)
  std::vector<Pose> T_base_gripper;          // refined robot poses
  std::vector<double> image_rms_px;          // per station
  std::vector<bool> image_outlier;           // RMS > 3 σ̂_px
  double rms_px = 0.0;                       // over every point
  double pixel_sigma = 0.0;                  // used (given or estimated)
  bool pixel_sigma_estimated = false;
  PoseSigma robot_sigma;  // used (given or estimated)
  bool robot_sigma_estimated = false;
  // The robot sigma the covariance is computed at: robot_sigma when given, else the posterior mean
  // (above, "Covariance").
  PoseSigma robot_sigma_covariance;
  pose::CameraModel camera;  // the intrinsics used: given, or refined
  // refine_intrinsics: their covariance (pose::IntrinsicsOf order; px², px, 1).
  std::optional<Eigen::Matrix<double, pose::kNumIntrinsics, pose::kNumIntrinsics>>
      intrinsics_covariance;
  // Per station, per point (the order of ImagePoints): π(B P_k) − u_k at the result (px).
  std::vector<std::vector<Eigen::Vector2d>> residuals_px;
};

// Requires T_base_gripper.size() == images.size() and a start (X0, Z0) close enough for the
// target to stay in front of every camera (the pose-level ml estimate). Throws DegenerateError
// for fewer than 3 images or 2m ≤ 12 pixel residuals, a non-finite start, a robot pose more than
// 100 m from the base (lengths in the wrong unit), a start that puts a target point behind a
// camera, and a non-finite solution; InputError for invalid sigmas and non-finite inputs.
ReprojectionResult RefineReprojection(const std::vector<Pose>& T_base_gripper,
                                      const std::vector<ImagePoints>& images, const Pose& X0,
                                      const Pose& Z0, const ReprojectionOptions& options);

}  // namespace hecal::estimation
