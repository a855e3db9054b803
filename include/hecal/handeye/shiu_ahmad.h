// Shiu & Ahmad (1989), "Calibration of wrist-mounted robotic sensors by solving homogeneous
// transform equations of the form AX = XB", IEEE Trans. Robotics and Automation 5(1):16–29 —
// the first closed-form solution: rotation from the rotation axes through a one-parameter family
// of solutions per motion and a linear system, then translation, from A_ij X = X B_ij
// (motion.h), station-pair motions.
//
// Equations. R_A R_X = R_X R_B means R_X maps the unit axis k_B of R_B onto the axis k_A of R_A,
// and every rotation doing so is
//        R_X = Rot(k_A, β) R_0,     R_0 any rotation with R_0 k_B = k_A            (Shiu 21)
// — one free angle β per motion. With orthonormal bases (e₁, e₂, k_B) and (f₁, f₂, k_A)
// (right-handed, R_0 e_m = f_m), this family is the circle
//        R_X = k_A k_Bᵀ + cos β (f₁e₁ᵀ + f₂e₂ᵀ) + sin β (f₂e₁ᵀ − f₁e₂ᵀ)
//            = U + cos β V + sin β W                                              (S1)
// in the 9-space of 3×3 matrices (U, V, W do not depend on which R_0 or bases are used; ⟨V, W⟩
// = ⟨U, V⟩ = ⟨U, W⟩ = 0, ‖V‖² = ‖W‖² = 2). Shiu & Ahmad equate the families of two motions,
// U_i + x_i V_i + y_i W_i = U_j + x_j V_j + y_j W_j with x = cos β, y = sin β as independent
// linear unknowns, and solve the stacked 9-row blocks by linear least squares.
//
// All pairs of motions, accumulated. Over every pair of motions i < j that least-squares
// problem is Σ_{i<j} ‖F_i − F_j‖² with F_i = U_i + x_i V_i + y_i W_i, and
// Σ_{i<j} ‖F_i − F_j‖² = N Σ_i ‖F_i − F̄‖², so it is the same as fitting one matrix r = vec R to
// all families, min over r and (x_i, y_i) of Σ_i ‖U_i + x_i V_i + y_i W_i − r‖². Eliminating
// (x_i, y_i) projects each residual off the plane span(V_i, W_i):
//        Σ_i ω_i P_i (r − u_i),   P_i = I₉ − ½ (v_i v_iᵀ + w_i w_iᵀ),   P_i u_i = u_i,
// and the 9×9 normal equations (Σ ω_i P_i) r = Σ ω_i u_i are accumulated without any 9N-row
// system. With column-major vec (vec(f eᵀ) = e ⊗ f) the projector needs no basis at all:
//        v vᵀ + w wᵀ = (I − k_B k_Bᵀ) ⊗ (I − k_A k_Aᵀ) + [k_B]× ⊗ [k_A]×,                (S2)
// so every motion adds two Kronecker products of 3×3 matrices (kronecker.h AddKronecker).
// R_X is the rotation nearest to vec⁻¹ r (nearest_rotation.h) —
// noise-free r is exactly vec R_X. The translation is the least-squares solution of
// (R_A − I) t_X = R_X t_B − t_A (translation.h; Shiu & Ahmad's own translation equation).
//
// Robustness:
//  - Weights ω_i = |a_v| |b_v| = sin(θ_A/2) sin(θ_B/2) (a, b the motion quaternions). Shiu & Ahmad
//  weight all motions equally,
//    but a unit axis is undefined at θ = 0 and its error grows like σ/θ; ω ≈ sin²(θ/2) is about
//    the inverse of that variance, makes ω_i u_i = vec(a_v b_vᵀ) and ω_i (S2) =
//    (|b_v| I − b_v b_vᵀ/|b_v|) ⊗ (|a_v| I − a_v a_vᵀ/|a_v|) + [b_v]× ⊗ [a_v]× well defined down
//    to θ → 0, and leaves the noise-free solution unchanged. No angle threshold is needed.
//  - Signs near π: the family needs k_A, k_B with consistent signs (R_X k_B = +k_A); noise flips
//    canonical axes of rotations near π. b's sign is aligned per motion against the sign-free
//    Kronecker estimate of R_X (rotation_init.h), valid for every angle including exactly π.
//  - k_A = −k_B (X a half-turn about an axis normal to k_B) is no special case: (S2) uses no
//    R_0 and no basis, so nothing is computed from k_A × k_B.
//  - X near π: no singularity (no angle parameter of X is solved for).
//  - Degenerate data: Σ ω_i P_i is singular when all axes are parallel: DegenerateError.
// Preconditions: motions from at least 3 stations with two non-parallel rotation axes.
#pragma once

#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/motion.h"

namespace hecal::handeye {

Pose SolveShiuAhmad(const std::vector<Motion>& motions);

}  // namespace hecal::handeye
