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
#include <utility>
#include <vector>

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

// The re-check of the matches at the polished X: the L∞ removal (global/outlier_removal.h)
// decides on the L∞ optimum, which is set by a few extreme pairs — it removes correct matches
// with the wrong one (the whole support set) and keeps wrong matches that the L∞ X happens to
// fit. At the polished X every pair of `all` (the problem before any removal) is kept iff
// |r| ≤ k σ (σ = ray_sigma, else 1.4826 · median |r| of the pairs kept so far, at least 1e-8),
// and the polish
// is repeated on the kept pairs until the set stops changing (at most 5 times).
struct RecheckedPolish {
  EpipolarPolish polish;
  global::EpipolarProblem inliers;           // the kept pairs of `all`
  std::vector<std::pair<int, int>> removed;  // (motion index, pair id) of the others
};

// Precondition: `inliers` (a subset of `all`, same motions in the same order) has ≥ 7 pairs.
RecheckedPolish PolishAndRecheck(const global::EpipolarProblem& all,
                                 const global::EpipolarProblem& inliers, const Pose& start,
                                 std::optional<double> ray_sigma = std::nullopt, double k = 3.5);

// The residual r above for one pair under X (radians of ray).
double SampsonAngle(const Pose& X, const Pose& hand_motion, const global::BearingPair& pair);

}  // namespace hecal::estimation
