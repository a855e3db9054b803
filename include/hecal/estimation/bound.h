// The first-order (Cramér–Rao-type) bound on the accuracy of any unbiased estimate of (X, Z)
// from a data set, given the robot and camera noise (the thesis study's bound figures, e.g. 0.54° /
// 2.8 mm, come from here).
//
// Linearised at the truth, every station gives r_i ≈ J_i δ + n_i with J_i = ∂r_i/∂(δX, δZ)
// (loop_residual.h) and n_i ~ N(0, Σ_i) (station_covariance.h); the true station poses are
// nuisance parameters already eliminated by the loop constraint (Gauss–Helmert model), so the
// Fisher information of δ = (δX, δZ) is
//        I = Σ_i J_iᵀ Σ_i⁻¹ J_i        (12 × 12, right perturbations, (ω, v) order each),
// and any unbiased estimator has Cov(δ̂) ⪰ I⁻¹ to first order. The ml method attains it
// asymptotically.
// Errors are measured as in the thesis (docs/thesis-study.md): rotation angle of X⁻¹X̂ and
// translation distance |t̂ − t|. With X̂ = X·Exp(δ), δ = (ω, v): the angle is |ω| exactly and
// t̂ − t = R·Jl(ω)·v = R·v + O(|ω||v|), so |t̂ − t| = |v| to first order. Hence
//        rotation RMSE bound    = sqrt(trace of the ω block of I⁻¹)
//        translation RMSE bound = sqrt(trace of the v block of I⁻¹).
// To compare an estimator over many simulated data sets, average the squared bounds:
// RMSE_bound = sqrt(mean_k bound_k²).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "hecal/estimation/pose_sigma.h"
#include "hecal/geometry/types.h"
#include "hecal/handeye/planar.h"
#include "hecal/handeye/problem.h"

namespace hecal::estimation {

// One station's term J_iᵀ Σ_i⁻¹ J_i of I (12 × 12, full symmetric), station i given as (A_i, B_i)
// of problem.h with its robot and camera covariances — what a planned station would add
// (plan/pose_plan.h).
Eigen::Matrix<double, 12, 12> StationInformation(handeye::Setup setup, const Pose& A,
                                                 const Pose& B, const Pose& X, const Pose& Z,
                                                 const Matrix6d& robot, const Matrix6d& camera);

struct AccuracyBound {
  Eigen::Matrix<double, 12, 12> covariance;  // I⁻¹, blocks (δX, δZ)
  double rotation_rmse_X = 0.0;              // radians
  double translation_rmse_X = 0.0;           // metres
  double rotation_rmse_Z = 0.0;
  double translation_rmse_Z = 0.0;
};

// `truth`: the noise-free problem (or the measured one; the Jacobians are then evaluated at
// the measurements); X, Z: the true unknowns; robot[i], camera[i]: station i's covariances of
// T_base_gripper_i and T_camera_target_i (right perturbations), mapped to Σ_i by
// station_covariance.h. Throws std::invalid_argument when there is not one robot and one camera
// covariance per station, hecal::DegenerateError when a station covariance is singular (e.g.
// every sigma zero: WhiteningMatrix) or the information is (degenerate data).
AccuracyBound FirstOrderBound(const handeye::Problem& truth, const Pose& X, const Pose& Z,
                              const std::vector<Matrix6d>& robot,
                              const std::vector<Matrix6d>& camera);

// The same sigmas at every station (PoseCovariance, pose_sigma.h).
AccuracyBound FirstOrderBound(const handeye::Problem& truth, const Pose& X, const Pose& Z,
                              const PoseSigma& robot_sigma, const PoseSigma& camera_sigma);

// Planar robots (handeye/planar.h): the bound when one coordinate of X's translation is given —
// the constrained inverse information (zero along the fixed coordinate), so the RMSE figures are
// of the observable part.
AccuracyBound FirstOrderBound(const handeye::Problem& truth, const Pose& X, const Pose& Z,
                              const PoseSigma& robot_sigma, const PoseSigma& camera_sigma,
                              const handeye::FixedTranslation& fixed);

}  // namespace hecal::estimation
