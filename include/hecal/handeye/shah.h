// Shah (2013), "Solving the robot-world/hand-eye calibration problem using the Kronecker
// product", ASME J. Mechanisms Robotics 5(3):031007 — closed-form, separable solution of the
// AX = YB problem on ABSOLUTE poses (no motions, so no noise correlation between pairs).
//
// hecal's form (problem.h): Z = A_i X B_i for every station i, i.e. A_i X = Z B_i⁻¹ — Shah's
// AX = YB with his A = A_i, X = X, Y = Z and his B = B_i⁻¹. Returns both X and Z.
//   rotation     R_Z = R_Ai R_X R_Bi  ⇔  vec(R_Z) = (R_Biᵀ ⊗ R_Ai) vec(R_X)   (kronecker.h K3)
//   translation  t_Z − R_Ai t_X = R_Ai R_X t_Bi + t_Ai
// Steps (Shah's method):
//  1. K = Σ_i R_Biᵀ ⊗ R_Ai (9×9, accumulated). Minimising Σ‖R_Ai R_X R_Bi − R_Z‖²_F over
//     rotations is maximising vec(R_Z)ᵀ K vec(R_X), so (vec R_Z, vec R_X) ∝ the left/right
//     singular vectors (u₁, v₁) of the largest singular value of K (noise-free it equals n).
//     Computed as v₁ = top eigenvector of KᵀK and u₁ = K v₁ / ‖K v₁‖.
//  2. Each of vec⁻¹(v₁), vec⁻¹(u₁) is a rotation times an unknown scale and sign: Shah's
//     α = sign(det V)/|det V|^{1/3} is realised as "sign by det > 0, then the nearest rotation"
//     (kronecker.h RotationFromSignFreeVec, NearestRotationSvd) — the scale never matters.
//  3. t_X, t_Z by linear least squares on the translation equation with R_X fixed
//     (translation_xz.h). hecal writes it on Z = A X B so that each residual is the
//     translation error of the predicted Z_i; Shah writes the same unknowns on A X = Z B⁻¹.
// Robustness: rotation matrices only, so nothing depends on angles, axes or quaternion signs —
// rotations near 0 and π need no special care. The singular vector is unique iff the two
// largest eigenvalues of KᵀK are separated; if (μ₁ − μ₂)/μ₁ < kShahMinGap (all relative robot
// rotations about parallel axes, pure translations) DegenerateError is thrown, as it is when
// the translation normal equations are singular.
// Preconditions: at least 3 stations whose relative rotations have two non-parallel axes.
#pragma once

#include "hecal/handeye/problem.h"

namespace hecal::handeye {

inline constexpr double kShahMinGap = 1e-10;

Solution SolveShah(const Problem& problem);

}  // namespace hecal::handeye
