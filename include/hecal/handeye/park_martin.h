// Park & Martin (1994), "Robot sensor calibration: solving AX = XB on the Euclidean group",
// IEEE Trans. Robotics and Automation 10(5):717–721 — rotation then translation of X from
// A_ij X = X B_ij (motion.h), station-pair motions.
//
// Equations (the paper's, whose A X = X B has the same orientation as hecal's: A robot motion,
// B camera motion). With the logarithms α = log R_A and β = log R_B (rotation vectors),
// R_A = R_X R_B R_Xᵀ gives
//        α = R_X β                                                               (Park 5)
// and the least-squares rotation min Σ‖α − R_X β‖² over SO(3) is
//        M = Σ β αᵀ,     R_X = (MᵀM)^(−1/2) Mᵀ                                    (Park 12)
// — the orthogonal polar factor of Mᵀ. The translation is then the least-squares solution of
// (R_A − I) t_X = R_X t_B − t_A (Park 13; translation.h).
//
// Implementation and robustness:
//  - The polar factor is computed by SVD with a determinant correction (NearestRotationSvd of
//    Mᵀ, nearest_rotation.h). For full-rank M with det > 0 this is exactly (Park 12); it also
//    returns the unique answer when M has rank 2 (two motions, or all motions in two axis
//    directions), the case for which Park & Martin add α₃ = α₁ × α₂ by hand. Rank ≤ 1 (all
//    axes parallel) throws DegenerateError.
//  - Near π the logarithm is ambiguous: a rotation by θ ≈ π about n is also a rotation by
//    2π − θ about −n, and noise decides which one log returns, independently for R_A and R_B —
//    a flipped pair enters as α ≈ −R_X β with the largest weight. hecal takes the logs from
//    quaternions whose signs are aligned against the sign-free Kronecker estimate of R_X
//    (rotation_init.h): α from a (canonical, |α| ≤ π) and β = 2 atan2(|b_v|, b_w) b_v/|b_v|
//    from the aligned b, which may have b_w < 0 and so |β| slightly above π. That is the SAME
//    rotation as R_B, written with the axis consistent with α, so (Park 5) holds for every
//    angle including exactly π.
//  - Near 0, α and β → 0: a motion's weight in M is ∝ θ², so the undefined axis of a near-zero
//    rotation does not matter and no threshold is needed.
// Preconditions: motions from at least 3 stations with two non-parallel rotation axes.
#pragma once

#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/motion.h"

namespace hecal::handeye {

Pose SolveParkMartin(const std::vector<Motion>& motions);

}  // namespace hecal::handeye
