// X and Z from a minimal set of three stations in closed form, the hypothesis of the station
// consensus (station_consensus.h): a few hundred floating-point operations, where Shah's solver
// (shah.h) on the same three stations spends most of its time on a 9 × 9 eigendecomposition.
//
// Stations a, b, c of Z = A_i · X · B_i (problem.h) give two motions relative to a,
//        M_j · X = X · N_j,   M_j = A_j⁻¹ · A_a,   N_j = B_j · B_a⁻¹   (j = b, c),
// so the rotation axes satisfy α_j = R_X · β_j (α_j, β_j the unit axes of R_Mj, R_Nj, from
// so3::Log; Shiu and Ahmad, IEEE T-RA 5(1), 1989; docs/handeye-methods.md).
// Rotation: two vector pairs, equal weights. The unit vectors s = α_b + α_c and d = α_b − α_c are
// orthogonal (|α_b| = |α_c|), and so are their β counterparts; the rotation that takes the frame
// (ŝ_β, d̂_β, ŝ_β × d̂_β) onto (ŝ_α, d̂_α, ŝ_α × d̂_α) is the least-squares (Wahba) rotation of the
// two pairs (the bisector solution: Markley, "Attitude determination using two vector
// measurements", NASA/CP-1999-209235) — exact on noise-free data, no SVD.
// Translations: R_Ai · t_X − t_Z = −t_Ai − R_Ai · R_X · t_Bi for the three stations, least
// squares by the 6 × 6 normal equations (as Shah's solver, translation_xz.h). R_Z: the rotation
// mean of R_Ai · R_X · R_Bi over the three stations (quaternions summed with aligned signs, then
// normalised: the chordal L2 mean, Hartley et al., "Rotation averaging", IJCV 103, 2013).
// Returns nullopt when the three stations do not fix X: a motion turns by less than
// kMinRotation, or the two axes are within kParallelAxes of parallel (observability.h), on
// either side.
#pragma once

#include <optional>

#include "hecal/handeye/problem.h"

namespace hecal::handeye {

// Stations a, b, c of `problem` (distinct, valid indices).
std::optional<Solution> SolveMinimal(const Problem& problem, size_t a, size_t b, size_t c);

}  // namespace hecal::handeye
