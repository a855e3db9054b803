// Daniilidis (1999), "Hand-eye calibration using dual quaternions", IJRR 18(3):286–298 — the
// method the thesis implemented (docs/handeye-methods.md#daniilidis). Solves A_ij X = X B_ij
// (motion.h) for rotation and translation together, from station-pair motions.
//
// Equations. With the unit dual quaternions ǎ = a + εa' of A_ij, b̌ = b + εb' of B_ij and
// x̌ = q + εq' of X (dual_quaternion.h: q' = ½ t q), A X = X B is ǎ x̌ = x̌ b̌. When the scalar
// parts agree (a_w = b_w, a'_w = b'_w: both motions have the same rotation angle θ and the same
// translation d along the screw axis — true for conjugate motions), its vector part is
//        [ a_v − b_v     [a_v + b_v]×   0            0           ] [ q  ]
//        [ a'_v − b'_v   [a'_v + b'_v]× a_v − b_v    [a_v + b_v]× ] [ q' ] = 0,     (D1)
// one 6×8 block S_ij per motion (the paper's S; docs/handeye-methods.md#daniilidis). Stacking all
// blocks into T (6N×8), x̌ lies in the null space of T, which is 2-D when two motions have
// non-parallel rotation axes: x̌ = λ₁ v₇ + λ₂ v₈ with v₇, v₈ the right singular vectors of the two
// smallest singular values, v_k = (u_k, w_k). The unit constraints qᵀq = 1 and qᵀq' = 0 give
//        λᵀ C λ = 0,   C = [ u₁ᵀw₁  ½(u₁ᵀw₂ + u₂ᵀw₁) ; ·  u₂ᵀw₂ ],                   (D2)
//        λᵀ U λ = 1,   U = [ u₁ᵀu₁  u₁ᵀu₂ ; ·  u₂ᵀu₂ ],                                (D3)
// the paper's quadratic in s = λ₁/λ₂ written homogeneously. Of the two roots of (D2) the paper
// keeps the one with the larger λᵀUλ (the other is the spurious null vector (0, q), whose real
// part vanishes); λ is then scaled to satisfy (D3).
//
// Implementation and robustness:
//  - T is never formed: with S_ij = [[M₁, 0], [M₂, M₁]], TᵀT = Σ [[M₁ᵀM₁ + M₂ᵀM₂, M₂ᵀM₁],
//    [M₁ᵀM₂, M₁ᵀM₁]] is accumulated as three 4×4 sums and its eigenvectors taken (the right
//    singular vectors of T; singular values are the square roots of the eigenvalues).
//  - Quaternion signs (why OpenCV 4.6's DANIILIDIS breaks on wide rotations): (D1) needs ǎ and
//    b̌ with consistent signs, ǎ = +x̌ b̌ x̌*. Canonical signs (w ≥ 0) are arbitrary near θ = π,
//    where a_w ≈ b_w ≈ 0. hecal chooses b's sign by comparing a with q_X b q̄_X for the
//    sign-free Kronecker estimate of R_X (rotation_init.h), which works for every angle
//    including exactly π; b' = ½ t_B b is formed after the sign is chosen, so it follows.
//  - Scalar-part consistency check (the paper's condition for (D1)): with consistent signs,
//    e_ij = |a_w − b_w| (≈ ½ sin(θ/2) |θ_A − θ_B|, no singularity at 0 or π) and
//    e'_ij = |a'_w − b'_w| (= ½ |sin(θ_A/2) d_A − sin(θ_B/2) d_B|, the pitch) are compared with
//    τ = max(floor, 5 · 1.4826 · median(e)) — five robust standard deviations of the data's own
//    disagreement, so noisy data lose only true outliers while noise-free data with one
//    corrupted station lose exactly the corrupted motions. Rejected motions are left out of TᵀT.
//    If more than half the motions are rejected the data are not consistent hand–eye motions
//    (wrong pose convention, units, pairing): DegenerateError.
//  - Near θ = 0 a motion contributes little (M₁ ≈ 0 — its axis is undefined), which is right:
//    nothing in (D1) divides by the angle, so small rotations are harmless.
//  - Units: the dual rows scale with the length unit, so translations are divided by their RMS
//    magnitude before forming ǎ, b̌ (and t_X scaled back): the balance between the rotation and
//    translation rows of T does not depend on metres vs millimetres.
//  - Singular-value check (docs/handeye-methods.md#daniilidis): noise-free σ₇ ≈ σ₈ ≈ 0 (reported,
//    tested; taken as square roots of eigenvalues of TᵀT they resolve down to ~1e-8 σ₁). If σ₆ is
//    also ≈ 0 (σ₆ < kDaniilidisRankTolerance · σ₁: rank 5, all rotation axes parallel, or pure
//    translations) the null space is 3-D and the translation along the common axis is not
//    observable: DegenerateError.
//  - The root choice uses λᵀUλ / |λ|² (independent of how λ is parameterised, so λ₂ → 0 is no
//    special case); if noise makes C definite (no real root) the direction minimising |λᵀCλ| is
//    used. The result is normalised as a dual quaternion (|q| = 1, q·q' = 0) before conversion.
// Preconditions: at least 2 motions with non-parallel rotation axes (3 stations).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/motion.h"

namespace hecal::handeye {

inline constexpr double kDaniilidisRankTolerance = 1e-5;  // σ₆ / σ₁ below this: rank 5
inline constexpr double kDaniilidisOutlierFactor = 5.0;   // robust standard deviations

// Diagnostics of one solve.
struct DaniilidisReport {
  Eigen::Matrix<double, 8, 1> singular_values;  // of T (translations normalised), descending
  std::vector<int> rejected;                    // indices of motions failing the scalar check
  double rotation_tolerance = 0.0;              // τ for |a_w − b_w|
  double translation_tolerance = 0.0;           // τ for |a'_w − b'_w| (normalised units)
};

// Throws DegenerateError (see above). `report` may be null.
Pose SolveDaniilidis(const std::vector<Motion>& motions, DaniilidisReport* report);
Pose SolveDaniilidis(const std::vector<Motion>& motions);

}  // namespace hecal::handeye
