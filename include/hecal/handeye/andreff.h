// Andreff, Horaud & Espiau (2001), "Robot hand-eye calibration using structure-from-motion",
// IJRR 20(3):228–248 — the linear (Kronecker-product) formulation of A_ij X = X B_ij
// (motion.h) from station-pair motions.
//
// Equations, re-derived for hecal's A X = X B with column-major vec (kronecker.h K1):
//   rotation     R_A R_X = R_X R_B  ⇔  R_A R_X R_Bᵀ = R_X  ⇔
//                (I₉ − R_B ⊗ R_A) vec(R_X) = 0                                         (A1)
//                (the paper's (I₉ − R_A ⊗ R_B) vec(R_X) = 0 uses row-major vec: same equation)
//   translation  R_A t_X + t_A = R_X t_B + t_X  ⇔
//                (t_Bᵀ ⊗ I₃) vec(R_X) + (I₃ − R_A) t_X = t_A                           (A2)
// The paper stacks (A1) and (A2) into one linear system in the 12 unknowns (vec R_X, t_X); it
// is not homogeneous (right-hand side t_A), so its least-squares solution is unique, and the
// translation rows (A2) constrain R_X too — through R_X t_B, which for robot stations a metre
// apart is a far stronger rotation constraint than (A1) when the relative rotations are small.
// (Measured on moderate-rotation data with 0.3 mm / 0.3° noise, daniilidis_andreff_opencv_test:
// rotation RMS error 0.51° jointly against 0.84° from (A1) alone.)
// hecal's steps:
//  1. Joint linear least squares on (A1)+(A2), the paper's form. Its 12×12 normal equations are
//     accumulated in closed form (K = R_B ⊗ R_A is orthogonal):
//        N_RR = Σ (2I₉ − K − Kᵀ) + (Σ t_B t_Bᵀ) ⊗ I₃,   N_Rt = Σ t_B ⊗ (I₃ − R_A),
//        N_tt = Σ (2I₃ − R_A − R_Aᵀ),   g_R = Σ t_B ⊗ t_A,   g_t = Σ (I₃ − R_A)ᵀ t_A,
//     and solved with a pivoted LDLT — O(81 N), no 12N-row matrix.
//  2. vec⁻¹ of the rotation part is not orthogonal under noise: it is replaced by its nearest
//     rotation (NearestRotationSvd; (A2) has already fixed its sign and scale).
//  3. Translation re-solve: the joint t_X fits the non-orthogonal matrix of step 1, so t_X is
//     recomputed by least squares on (A2) for the orthogonalised R_X (translation.h). OpenCV
//     4.6's ANDREFF stops after step 2 with the joint t_X — reportedly ~3 cm off on the
//     rwhe-kuka2 data.
// Units: (A1) is dimensionless and (A2) has the length unit, so every translation is divided by
// the RMS translation magnitude before step 1 (and t_X scaled back): the noise-free solution is
// unchanged and the noisy one no longer depends on metres vs millimetres.
// Robustness: rotation matrices only — no angles, axes or quaternions — so there is no
// singularity or sign ambiguity at θ = 0 or θ = π; motions near θ = 0 contribute ≈ 0 to (A1)
// and to the t_X columns of (A2). Degenerate data (no two motions with non-parallel rotation
// axes, pure translations: the normal matrix is singular, min |D| / max |D| of its LDLT below
// kAndreffMinPivotRatio) throw DegenerateError, as does the translation re-solve.
// Preconditions: motions from at least 3 stations with two non-parallel rotation axes.
#pragma once

#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/motion.h"
#include "hecal/handeye/planar.h"

namespace hecal::handeye {

inline constexpr double kAndreffMinPivotRatio = 1e-12;

Pose SolveAndreff(const std::vector<Motion>& motions);

// The same with one coordinate of X's translation given (planar robots, planar.h): (A1)+(A2)
// solved as an equality-constrained least-squares problem (the KKT system), and the translation
// re-solve likewise. Throws DegenerateError when even then the system is singular.
Pose SolveAndreff(const std::vector<Motion>& motions, const TranslationFix& fix);

}  // namespace hecal::handeye
