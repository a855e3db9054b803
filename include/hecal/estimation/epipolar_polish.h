// The L2 polish of a target-free hand–eye solution (docs/global.md): the X = T_hand_camera
// that minimises the sum of squared angular Sampson errors of the bearing pairs kept as inliers,
// started from the global method's L∞ optimum (global/branch_and_bound.h), and its covariance.
// Heller, Havlena, Pajdla, TPAMI 38(5), 2016, §6 polish the L∞ optimum by an L2 refinement.
//
// Residual of a pair (v, u) under X (camera motion A = X⁻¹ B X, epipolar_problem.h):
//   r = v·(R_A u × t_A) / sqrt(|P_v (R_A u × t_A)|² + |P_u R_Aᵀ(t_A × v)|²),
// P_x = I − x xᵀ: the epipolar triple product over its first-order standard deviation when each
// ray is perturbed isotropically in its tangent plane by one radian — so r has the ray noise's
// standard deviation σ_ray (radians; ≈ pixel σ / focal length) whatever the geometry.
// Unknowns: X = X̂ · Exp(δ), δ = (ω, v) right perturbation (docs/conventions.md), solved by Ceres.
// Covariance: σ̂² (JᵀJ)⁻¹ in δ, with σ̂² = Σr²/(N − 6) (or the given σ_ray²); metres, radians.
#pragma once

#include <optional>

#include "hecal/geometry/types.h"
#include "hecal/global/epipolar_problem.h"

namespace hecal::estimation {

struct EpipolarPolish {
  Pose X = Pose::Identity();
  Matrix6d covariance = Matrix6d::Zero();  // of δ = (ω, v) at X
  double ray_sigma = 0.0;                  // radians: used (given or estimated)
  double rms = 0.0;                        // radians: RMS residual at X
  int pairs = 0;
};

// Precondition: at least 7 pairs. `ray_sigma` in radians (nullopt: estimated from the fit).
EpipolarPolish PolishEpipolar(const global::EpipolarProblem& problem, const Pose& start,
                              std::optional<double> ray_sigma = std::nullopt);

// The residual r above for one pair under X (radians of ray).
double SampsonAngle(const Pose& X, const Pose& hand_motion, const global::BearingPair& pair);

}  // namespace hecal::estimation
