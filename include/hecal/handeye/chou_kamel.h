// Chou & Kamel (1991), "Finding the position and orientation of a sensor on a robot manipulator
// using quaternions", IJRR 10(3):240–254 — rotation then translation of X from A_ij X = X B_ij
// (motion.h) with unit quaternions, the rotation from a structured homogeneous linear system
// solved by singular value decomposition.
//
// Equations. With the unit quaternions a = (cos(θ/2), sin(θ/2) k_A) of R_A, b of R_B and q of
// R_X, R_A R_X = R_X R_B is a q = q b; conjugate rotations have the same angle, so a_w = b_w and
// the common factor sin(θ/2) divides out of the vector parts, leaving for each motion
//        B_i q = 0,   B_i = [ 0          −(k_A − k_B)ᵀ ]
//                           [ k_A − k_B   [k_A + k_B]×  ]  = Q(k_A) − W(k_B)        (CK)
// in the unit rotation axes k_A, k_B (Q, W: quaternion_matrices.h). Each 4×4 B_i has rank 2;
// two motions with non-parallel axes give rank 3, and q is the right singular vector of the
// smallest singular value of the stacked system [B_1; B_2; …] (Chou & Kamel use two motions;
// hecal stacks every station-pair motion of motion.h — the least-squares generalisation). The
// translation follows from (R_A − I) t_X = R_X t_B − t_A in least squares (translation.h).
//
// Implementation and robustness:
//  - The 4N×4 stack is never formed: its 4×4 triangular factor R is updated 16 motions at a
//    time (Householder QR of the fixed-size 68×4 matrix [R; B_i; …], no allocation), and q is taken
//    from the SVD of R, which has the singular values and right singular vectors of the stack.
//    (Unlike the normal-equation eigenproblem of horaud.h, the singular values are not squared.)
//  - Unit axes, as in the paper: every motion has the same weight, whatever its angle. That is
//    what distinguishes this solver from horaud.h (axes weighted by sin(θ/2)); the price is that
//    a small rotation's axis — error ≈ σ/θ, undefined at θ = 0 — counts fully. hecal therefore
//    uses only motions whose robot rotation angle is at least kChouKamelMinAngleFraction of the
//    largest one in the data (a scale-free rule: pure translations and near-zero rotations
//    drop out, the rest keep Chou & Kamel's equal weights); if those do not determine q (their
//    axes are all parallel) it falls back to every motion rotating by more than kMinRotation
//    (observability.h).
//  - Signs near π: (CK) needs k_A, k_B from quaternions with consistent signs (a = +q b q̄).
//    Canonical signs are arbitrary near θ = π, where noise flips an axis; hecal aligns b's sign
//    per motion against the sign-free Kronecker estimate of R_X (rotation_init.h), valid for
//    every angle including exactly π.
//  - X near π: no singularity (q is a unit 4-vector).
//  - Degenerate data (no two non-parallel axes) throw DegenerateError.
// Preconditions: motions from at least 3 stations with two non-parallel rotation axes.
#pragma once

#include <vector>

#include "hecal/geometry/types.h"
#include "hecal/handeye/motion.h"

namespace hecal::handeye {

inline constexpr double kChouKamelMinAngleFraction = 0.1;

Pose SolveChouKamel(const std::vector<Motion>& motions);

}  // namespace hecal::handeye
