// Maximum-likelihood refinement of a camera pose from known points: Levenberg–Marquardt on the
// reprojection error over SE(3), and the pose's first-order covariance. The "natural extension"
// of the linear pose paper (docs/pose-from-points.md: its translation cannot be improved after its
// step 3).
//
// Model: pixel u_k = π(T · P_k) + e_k, e_k ~ N(0, σ² I₂), π = Project (camera_model.h), object
// points P_k exact. Minimise C(T) = ½ Σ ‖π(T P_k) − u_k‖² over T = T_camera_target.
// Parameterisation (docs/conventions.md): right perturbation T = T̂ · Exp(δ), δ = (ω, v)
// (se3::Exp), re-linearised at every accepted step. With p = T̂ P_k the point in the camera frame,
//   ∂p/∂δ = R̂ [ −[P_k]×  I ],    ∂r_k/∂δ = J_π(p) R̂ [ −[P_k]×  I ]      (2 × 6, analytic).
// Steps: (JᵀJ + μ diag(JᵀJ)) δ = −Jᵀr (Marquardt's scaling: ω in radians and v in metres differ in
// scale). A step is accepted when it lowers the cost, with every point staying in front of the
// camera (z > 0); μ then shrinks by max(1/3, 1 − (2ρ − 1)³) with ρ the ratio of actual to
// predicted decrease, else μ grows by ν and ν doubles (Nielsen's rule; Madsen, Nielsen &
// Tingleff, "Methods for Non-Linear Least Squares Problems", 2004, §3.2). So a poor start — e.g. a
// closed-form estimate from noisy points — takes short steps until the model fits.
// Stops when a step lowers the cost — or the damped linear model predicts it would lower it — by
// at most options.relative_cost_tolerance of it (converged), when no step lowers it any more (μ
// beyond 1e16: converged at the rounding floor, as noise-free data end), or after
// options.max_iterations steps (converged = false; the best pose so far is returned). μ starts at
// 1e-3.
//
// Covariance: Σ = σ² (JᵀJ)⁻¹ at the solution, 6×6, right perturbation of T_camera_target,
// (rx, ry, rz, tx, ty, tz), rad² / rad·unit / unit² in the object points' length unit. σ is
// options.pixel_sigma when given (SigmaSource::kGiven), else estimated from the residuals as
// σ̂ = sqrt(SSR / (2N − 6)) (kEstimated; unbiased for σ² when the model is right). The estimated
// form needs 2N > 6.
//
// Why Eigen and not Ceres (used by the estimation layer): speed and footprint. With 6 unknowns
// the 6×6 normal equations are solved directly; a plain loop has no problem set-up, no
// allocation per residual block and no sparse machinery, and keeps this module Eigen-only
// (small machines: docs/architecture.md#layers): measured 10–20 µs for 6–20 points and 20–50 µs for 50
// points (4–5 iterations from a closed-form start; one core of the shared development machine).
//
// Errors: InputError for mismatched or non-finite inputs, fewer than 3 points, invalid options;
// DegenerateError when the start puts a point behind the camera (z ≤ 0), when JᵀJ is singular at
// the solution (the points do not determine the pose, e.g. all on one line), or when σ must be
// estimated from 2N − 6 ≤ 0 degrees of freedom.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/pose/camera_model.h"

namespace hecal::pose {

struct RefinementOptions {
  int max_iterations = 100;
  double relative_cost_tolerance = 1e-14;
  std::optional<double> pixel_sigma;  // px, > 0; nullopt: estimated from the residuals

  // core/options_check.h: false naming RefinementOptions.max_iterations (below 1),
  // .relative_cost_tolerance (negative) or .pixel_sigma (given and not positive and finite).
  bool IsValid(std::string* why) const;
};

enum class SigmaSource { kGiven, kEstimated };
// "given" | "estimated".
std::string_view SigmaSourceName(SigmaSource source);

struct RefinementResult {
  Pose T_camera_target = Pose::Identity();
  std::vector<Eigen::Vector2d> residuals_px;  // π(T P_k) − u_k, per point
  double rms_px = 0.0;                        // sqrt(Σ ‖residual‖² / N)
  Matrix6d covariance = Matrix6d::Zero();     // see above
  double sigma_px = 0.0;                      // σ used for the covariance
  SigmaSource sigma_source = SigmaSource::kEstimated;
  int iterations = 0;  // accepted and rejected steps
  bool converged = false;
};

RefinementResult RefinePose(const Pose& initial_T_camera_target,
                            const std::vector<Eigen::Vector3d>& object_points,
                            const std::vector<Eigen::Vector2d>& pixels, const CameraModel& camera,
                            const RefinementOptions& options = {});

// The residuals π(T P_k) − u_k and their RMS (px) for a given pose, e.g. one not refined.
// DegenerateError when a point is behind the camera.
std::vector<Eigen::Vector2d> ReprojectionResiduals(
    const Pose& T_camera_target, const std::vector<Eigen::Vector3d>& object_points,
    const std::vector<Eigen::Vector2d>& pixels, const CameraModel& camera);
double RmsPx(const std::vector<Eigen::Vector2d>& residuals);

}  // namespace hecal::pose
