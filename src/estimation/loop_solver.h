// Internal: ml's cost with the station whitening held fixed, its normal equations, and the
// Levenberg–Marquardt minimiser ml runs on it (ml.h).
//
// Cost over (X, Z) ∈ SE(3) × SE(3):
//        F(X, Z) = Σ_i ρ(s_i),   s_i = |W_i r_i|²,   r_i = Log(Z⁻¹ A_i X B_i)  (loop_residual.h)
// with W_i the whitening of station i (station_covariance.h) and ρ the robust loss (robust_loss.h;
// ρ(s) = s without one). Normal equations at (X, Z) over the right perturbations δ = (δX, δZ)
// (ω, v order each; docs/conventions.md), with J_i = ∂r_i/∂δ (loop_residual.h) and w_i = ρ'(s_i):
//        H = Σ_i w_i (W_i J_i)ᵀ (W_i J_i),        g = Σ_i w_i (W_i J_i)ᵀ W_i r_i.
// g is exactly the gradient of F/2; H is the Gauss–Newton Hessian with the robust weights frozen
// at the current point (iteratively reweighted least squares). Without a robust loss this is
// plain Gauss–Newton; with one, the minimiser stops at a stationary point of F like any descent
// method on F, so it reaches the optimum Ceres reaches with Triggs' ρ'' correction (Triggs et al.,
// "Bundle Adjustment — A Modern Synthesis", 2000, §4.3) from the same start.
//
// Minimiser: Levenberg–Marquardt with Marquardt's diagonal (Madsen, Nielsen & Tingleff, "Methods
// for Non-Linear Least Squares Problems", 2004, §3.2), trust region Δ as in Ceres Solver's
// LEVENBERG_MARQUARDT strategy: a step solves (H + D/Δ) δ = −g with D = diag(H) clamped to
// [1e-6, 1e32], moves X ← X·Exp(δX), Z ← Z·Exp(δZ), and is accepted when F/2 falls by at least
// 1e-3 of the model's predicted decrease −(gᵀδ + ½ δᵀHδ); then Δ ← Δ / max(1/3, 1 − (2q − 1)³)
// (q = actual / predicted decrease), otherwise Δ ← Δ/ν, ν ← 2ν. Starts at Δ = 1e4. Stops as
// hecal's Ceres refinements do (small_problem.h): relative decrease of F ≤ 1e-14, |g|∞ ≤ 1e-16,
// |δ| ≤ 1e-13 · (|x| + 1e-13) with |x|² = 2 + |t_X|² + |t_Z|² (the norm of the two 7-double
// quaternion-and-translation parameter blocks), or 100 iterations; and, checked after every
// linearisation, when the largest decrease the Gauss–Newton model still promises, ½ gᵀH⁻¹g, is
// at most 1e-14 of F/2. (Without that last rule the minimiser, like Ceres, spends several rejected
// steps at the optimum, where the change of F is rounding noise of order 1e-13 · F.)
// Why by hand: the problem has 12 unknowns and the 12 × 12 normal equations are accumulated
// directly from the analytic Jacobians; at n = 50 stations building a Ceres problem and its
// dense QR of the 6n × 12 Jacobian cost several times the evaluations themselves.
#pragma once

#include <ceres/loss_function.h>

#include <vector>

#include "hecal/estimation/loop_residual.h"
#include "hecal/handeye/planar.h"
#include "hecal/handeye/problem.h"

namespace hecal::estimation::internal {

using Matrix12d = Eigen::Matrix<double, 12, 12>;
using Vector12d = Eigen::Matrix<double, 12, 1>;

struct LoopNormalEquations {
  double cost = 0.0;  // F
  Matrix12d hessian = Matrix12d::Zero();
  Vector12d gradient = Vector12d::Zero();
};

// F at `solution`; `whitening` has one W_i per station of `problem`, `loss` may be null.
double LoopCostValue(const handeye::Problem& problem, const std::vector<Matrix6d>& whitening,
                     const ceres::LossFunction* loss, const handeye::Solution& solution);

// F, H and g at `solution`.
LoopNormalEquations LinearizeLoopCost(const handeye::Problem& problem,
                                      const std::vector<Matrix6d>& whitening,
                                      const ceres::LossFunction* loss,
                                      const handeye::Solution& solution);

// The minimiser above from `start`. Returns the last accepted point (`start` when no step was).
// With `fixed` (planar.h): on the surface where X's fixed coordinate has its value — start and
// every candidate moved onto it along the planar family, the steps on its tangent.
handeye::Solution MinimizeLoopCost(const handeye::Problem& problem,
                                   const std::vector<Matrix6d>& whitening,
                                   const ceres::LossFunction* loss, const handeye::Solution& start,
                                   const handeye::FixedTranslation* fixed = nullptr);

}  // namespace hecal::estimation::internal
