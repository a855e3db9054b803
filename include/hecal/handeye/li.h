// Li, Wang & Wu (2010), "Simultaneous robot-world and hand-eye calibration using
// dual-quaternions and Kronecker product", Int. J. Physical Sciences 5(10):1530–1536 — the
// Kronecker-product form: ONE linear least-squares system in rotation and translation of both
// unknowns, on ABSOLUTE poses. Returns X and Z.
//
// hecal's form (problem.h): Z = A_i X B_i, written as Li's AX = YB with C_i = B_i⁻¹:
//        A_i X = Z C_i.
// Its rotation and translation parts are linear in w = (vec R_X, vec R_Z, t_X, t_Z) (24
// unknowns; column-major vec, kronecker.h K1):
//        (I₃ ⊗ R_Ai) vec(R_X) − (R_Ciᵀ ⊗ I₃) vec(R_Z)               = 0      (9 rows)   (L1)
//        R_Ai t_X − (t_Ciᵀ ⊗ I₃) vec(R_Z) − t_Z                     = −t_Ai  (3 rows)   (L2)
// (the paper's system, there with row-major vec). Because of the right-hand side −t_Ai the
// system is not homogeneous: the translations fix the scale of the rotation unknowns.
// Steps:
//  1. The 24×24 normal equations Σ L_iᵀ L_i w = Σ L_iᵀ c_i are accumulated in closed form
//     from 9×9 / 9×3 / 3×3 blocks (no 12n×24 matrix): with R_Ci = R_Biᵀ they need
//     Σ R_Bi ⊗ R_Aiᵀ, Σ t_Ci t_Ciᵀ ⊗ I₃, Σ t_Ci ⊗ R_Ai, Σ t_Ci, Σ R_Ai, Σ t_Ci ⊗ t_Ai, …
//     and are solved with a pivoted LDLT.
//  2. vec⁻¹ of the rotation parts are not exactly orthogonal under noise: each is replaced by
//     its nearest rotation (NearestRotationSvd; the sign is already fixed by (L2)).
//  3. Translation re-solve: the t_X, t_Z of step 1 fit the non-orthogonal matrices, so they are
//     recomputed by linear least squares with the orthogonalised R_X (translation_xz.h, the
//     same step as Shah's). Noise-free this changes nothing; with noise it makes the returned
//     translations the best ones for the returned rotations.
// Units: (L1) is dimensionless and (L2) has the length unit, so the weight of (L2) would depend
// on metres vs millimetres. hecal divides every translation by the RMS translation magnitude
// before forming the system (and scales t_X, t_Z back): the noise-free solution is unchanged,
// and the noisy one no longer depends on the unit.
// Robustness: rotation matrices only, no angles/axes/quaternions, so rotations near 0 and π need
// no care. Degenerate data (all relative robot rotations about parallel axes, pure translations:
// the normal matrix is singular) throw DegenerateError — checked on the LDLT pivots
// (min |D| / max |D| < kLiMinPivotRatio) and again by the translation re-solve.
// Preconditions: at least 3 stations whose relative rotations have two non-parallel axes.
#pragma once

#include "hecal/handeye/problem.h"

namespace hecal::handeye {

inline constexpr double kLiMinPivotRatio = 1e-12;

Solution SolveLi(const Problem& problem);

}  // namespace hecal::handeye
