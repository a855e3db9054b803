// Horaud & Dornaika (1995), "Hand-eye calibration", IJRR 14(3):195–210, §5 — the closed-form
// "R then t" variant (docs/handeye-methods.md#horaud-and-dornaika): rotation of X as a
// unit-quaternion eigenproblem, then the translation by linear least squares, from A_ij X = X B_ij
// (motion.h), station-pair motions. (The simultaneous nonlinear "R and t" variant is
// horaud_nonlinear.h.)
//
// Equations. Each motion gives v'_i = R_X v_i for its rotation axes (v'_i of A_ij, v_i of
// B_ij). With R_X v = q v q̄ and ‖r q‖ = ‖r‖ ‖q‖ for quaternions,
//        f₁(q) = Σ ‖v'_i − q v_i q̄‖² = Σ ‖v'_i q − q v_i‖² = qᵀ A q,
//        A = Σ (Q(v'_i) − W(v_i))ᵀ (Q(v'_i) − W(v_i))                      (thesis eq. 2.8)
// with Q, W the left/right quaternion-product matrices (quaternion_matrices.h); the unit q
// minimising f₁ is the eigenvector of the smallest eigenvalue of the 4×4 symmetric A. Then t_X
// minimises f₂ = Σ ‖R_X p_i − (K_i − I) t − p'_i‖² (K_i = R_Aij, p'_i = t_Aij, p_i = t_Bij),
// i.e. (R_A − I) t_X = R_X t_B − t_A in least squares (translation.h).
//
// Choices and robustness:
//  - Quaternion form. hecal uses the motions' full unit quaternions a (of R_A) and b (of R_B)
//    in place of the axis quaternions: A = Σ (Q(a) − W(b))ᵀ(Q(a) − W(b)), the paper's
//    quaternion statement a q = q b of R_A R_X = R_X R_B. Because Q(a_v) − W(b_v) is
//    skew-symmetric, the scalar parts only add the constant (a_w − b_w)² to f₁, so this is f₁
//    with v'_i = a_v = sin(θ/2) n_A and v_i = b_v: the rotation axes weighted by sin(θ/2).
//    Same noise-free solution as unit axes; but a unit axis is undefined as θ → 0 and its error
//    grows like σ/θ, while the weighted axis has bounded error and vanishing weight, so near-zero
//    motions need no threshold.
//  - Signs. f₁ needs a = +q_X b q̄_X. The usual rule (choose b's sign so that a_w b_w ≥ 0) is
//    only reliable away from π: near π both scalar parts are ≈ 0 and noise picks the signs (this
//    is what breaks OpenCV 4.6's HORAUD on wide rotations). hecal chooses b's sign per motion
//    by comparing a with q_X b q̄_X for the sign-free Kronecker estimate of R_X
//    (rotation_init.h AlignQuaternions) — valid for every angle including exactly π.
//  - X near π: no singularity (q_X is a unit 4-vector, any rotation is as good as any other).
//  - Degenerate data: when the two smallest eigenvalues of A are not separated (all axes
//    parallel) DegenerateError is thrown; the translation step throws for its own degeneracy.
// Preconditions: motions from at least 3 stations with two non-parallel rotation axes.
#pragma once

#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/motion.h"

namespace hecal::handeye {

Pose SolveHoraud(const std::vector<Motion>& motions);

}  // namespace hecal::handeye
