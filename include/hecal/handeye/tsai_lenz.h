// Tsai & Lenz (1989), "A new technique for fully autonomous and efficient 3D robotics hand/eye
// calibration", IEEE Trans. Robotics and Automation 5(3):345–358
// (docs/handeye-methods.md#tsai-and-lenz) — rotation then translation of X from A_ij X = X B_ij
// (motion.h), station-pair motions.
//
// Frames: A_ij is the robot motion (Tsai's gripper motion H_gij), B_ij the camera motion (Tsai's
// H_cij), X as in problem.h (eye-in-hand T_gripper_camera — Tsai's H_cg). So hecal's equation
// is Tsai's H_gij H_cg = H_cg H_cij with g = A and c = B.
//
// Equations (re-derived for A X = X B). Tsai's modified Rodrigues vector of a rotation by θ
// about n is P = 2 sin(θ/2) n = 2 × (vector part of its unit quaternion) (rotation.h,
// TsaiRodrigues). Writing R_A R_X = R_X R_B with quaternions a q = q b, q = (cos(θ_X/2),
// sin(θ_X/2) n_X), and using a_w = b_w (conjugate rotations have the same angle), the vector
// part gives (a_v + b_v) × sin(θ_X/2) n_X = cos(θ_X/2) (b_v − a_v); with
// P'_X = tan(θ_X/2) n_X (Tsai eq. 9, P'_cg = P_cg / (2 cos(θ_X/2))):
//        skew(P_A + P_B) P'_X = P_B − P_A                                           (Tsai 12)
// one rank-2 3×3 block per motion, solved in least squares over all motions via the 3×3 normal
// equations; then θ_X = 2 atan|P'_X| (eq. 13), i.e. q_X = (1, P'_X) / √(1 + |P'_X|²). The
// translation step (eq. 15–16) is translation.h: (R_A − I) t_X = R_X t_B − t_A.
//
// Robustness (the failure modes of a literal implementation such as OpenCV 4.6's TSAI):
//  - X near π: P'_X = tan(θ_X/2) n_X is infinite at θ_X = π, and the least-squares system is
//    ill-conditioned long before. hecal solves in a pre-rotated frame: with R0 the sign-free
//    Kronecker estimate of R_X (rotation_init.h SignFreeRotation), X = X̃ R0 turns A X = X B
//    into A X̃ = X̃ B̃ with B̃ = R0 B R0ᵀ (P_B̃ = R0 P_B), whose solution X̃ = X R0ᵀ is close to
//    the identity, so |P'_X̃| is small whatever θ_X. Then R_X = R̃ R0. Noise-free the result is
//    exact either way; with noise Tsai's least squares is not frame-invariant (it weights the
//    quaternion residual by 1/cos²(θ_X/2)), and the pre-rotated frame is where that weight is ≈ 1.
//    There (Tsai 12)'s residual is the vector part of a q̃ − q̃ b̃ divided by cos(θ̃/2) ≈ 1 and
//    the dropped scalar part is second order, so the estimate agrees with Horaud–Dornaika's
//    quaternion least squares (horaud.h) to first order in the noise.
//  - Motions near π: (Tsai 12) needs P_A, P_B from quaternions of consistent sign
//    (a = +q b q̄); canonical signs (w ≥ 0) are arbitrary near π, where a_w ≈ b_w ≈ 0, and a
//    flipped pair turns the equation into skew(P_A − P_B) P'_X = −(P_A + P_B) — garbage with
//    the largest weight. b's sign is chosen per motion against R0 (rotation_init.h
//    AlignQuaternions), valid for every angle including exactly π. These motions are then the
//    most informative ones (|P| ≈ 2).
//  - Motions near 0: P_A, P_B → 0, so the block and its right-hand side vanish; the axis, which
//    is undefined there, gets weight ∝ sin²(θ/2) and no threshold is needed. Tsai's advice to
//    drop such pairs is therefore unnecessary here.
//  - Degenerate data (no two motions with non-parallel axes) throw DegenerateError (from
//    SignFreeRotation, the normal equations or the translation step).
// Preconditions: motions from at least 3 stations with two non-parallel rotation axes.
#pragma once

#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/motion.h"

namespace hecal::handeye {

Pose SolveTsaiLenz(const std::vector<Motion>& motions);

}  // namespace hecal::handeye
