// Horaud & Dornaika (1995), "Hand-eye calibration", IJRR 14(3):195–210, §5 — the simultaneous
// nonlinear variant (docs/handeye-methods.md#horaud-and-dornaika, "R and t together"): rotation and
// translation of X from A_ij X = X B_ij (motion.h) by minimising over the 7 unknowns (q ∈ ℝ⁴, t ∈
// ℝ³)
//        F(q, t) = λ₁ f₁(q) + λ₂ f₂(q, t) + λ (1 − qᵀq)²,                               (H1)
//        f₁(q)    = Σ ‖v'_i q − q v_i‖²           = qᵀ A q,  A = Σ (Q(v'_i) − W(v_i))ᵀ(…)  (H2)
//        f₂(q, t) = Σ ‖q p_i q̄ − (K_i − I) t − p'_i‖²                                     (H3)
// with, per motion, K_i = R_Aij, p'_i = t_Aij, p_i = t_Bij, and v'_i, v_i the rotation-axis
// quaternions of A_ij and B_ij (v'_i = R_X v_i); Q, W are the quaternion product matrices of
// quaternion_matrices.h. (H3) is the translation equation (R_A − I) t_X = R_X t_B − t_A with
// R_X p written as q p q̄, which is quadratic in q and exact only for ‖q‖ = 1 — hence the penalty.
//
// Choices (the paper leaves them open) and why:
//  - Axes: v'_i, v_i are the VECTOR PARTS of the motion quaternions, sin(θ/2)·axis, not unit
//    axes. Same noise-free solution; a motion whose angle is near 0 — where the axis is pure
//    noise — gets weight sin²(θ/2) → 0 instead of 1, so near-zero rotations need no threshold.
//  - Signs near π: v' and v must come from quaternions with consistent signs (a = +q_X b q̄_X);
//    near θ = π a canonical w ≥ 0 choice flips them at random. They are aligned against the
//    starting rotation (rotation_init.h AlignQuaternions), valid for every angle including π.
//  - Weights, scale-free: λ₁ = 1/s₁², λ₂ = 1/s₂² where s₁², s₂² are the mean squared rotation
//    and translation residuals per motion at the closed-form start (so each term starts at ≈ N
//    whatever the length unit; an approximation of inverse noise-variance weighting). Exact data
//    have zero residuals: s₁², s₂² are floored at 1e-12 × the mean squared magnitude of the
//    corresponding data (‖v'_i‖², ‖p'_i‖² and ‖p_i‖²), which keeps the ratio meaningful.
//  - Penalty: λ = 100 · (λ₁ Σ‖v_i‖² + λ₂ Σ‖p_i‖²), i.e. 100 × the data terms' own curvature in
//    the radial direction of q, so ‖q‖ stays within ~1e-2 × (residual/magnitude)² of 1 while the
//    7×7 system stays well conditioned.
//  - Minimiser: Levenberg–Marquardt with analytic Jacobians on fixed-size 7×7 normal equations.
//    Both terms are quadratic forms accumulated ONCE: f₁ = qᵀAq (4×4) and
//    f₂ = zᵀ H z with z = (vec R̃(q), t, 1) ∈ ℝ¹³, R̃(q) p = q p q̄, H = Σ L_iᵀ L_i (13×13, from
//    closed-form blocks). Each iteration is then O(1), independent of the number of motions.
//  - Start: the closed-form R-then-t variant of the same paper (horaud.h: q minimising f₁, then
//    t minimising f₂) — the LM only has to trade rotation against translation residuals.
//  - Finish: q is normalised (the penalty leaves ‖q‖ ≈ 1, not = 1) and t re-solved as the exact
//    minimiser of f₂ for that unit q, t = −H_tt⁻¹ (H_tR vec R + H_t1).
// Degenerate data (parallel rotation axes, pure translations, fewer than 2 motions) throw
// DegenerateError from the start or from the translation step.
#pragma once

#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/motion.h"

namespace hecal::handeye {

Pose SolveHoraudNonlinear(const std::vector<Motion>& motions);

// The refinement alone, from a starting rotation within ~90° of the truth (start's translation
// is not used: the LM starts from the translation minimising f₂ for start's rotation).
Pose RefineHoraudNonlinear(const std::vector<Motion>& motions, const Pose& start);

}  // namespace hecal::handeye
