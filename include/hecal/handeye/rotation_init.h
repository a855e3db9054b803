// A sign-free initial estimate of R_X for AX = XB, and quaternions of a motion with consistent
// signs — what the quaternion-based solvers need so that they do not break near π.
//
// Why: a motion's rotations R_A = R_X R_B R_Xᵀ have unit quaternions a and b with
//        a = ± q_X · b · q̄_X,
// and the quaternion solvers (Daniilidis' dual-quaternion equations, Horaud–Dornaika's f1, ...)
// are only valid for the + sign. The usual canonical choice (w ≥ 0 for both) fails near π: there
// a_w ≈ b_w ≈ 0 and measurement noise picks the two signs independently, so about half of the
// wide motions enter with the wrong sign (this is what breaks OpenCV 4.6's DANIILIDIS on wide
// rotations). Comparing the two quaternions through an estimate of R_X removes the ambiguity:
//        s = sign(a · (q_X b q̄_X)) = sign(a_w b_w + a_v · (R_X b_v)),
// which is ≈ ±1 for every angle (including exactly π) as long as the estimate of R_X is within
// 90° of the truth — the estimate below is far better than that whenever the data are not
// degenerate.
//
// SignFreeRotation: the least-squares rotation from the rotation rows alone of Andreff, Horaud &
// Espiau's (2001) linear formulation (andreff.h (A1)), which never looks at quaternions or
// rotation axes and is therefore free of any sign or near-π issue.
// From kronecker.h (K2), every motion gives (I₉ − R_Bij ⊗ R_Aij) vec(R_X) = 0; with
// K_ij = R_Bij ⊗ R_Aij orthogonal,
//        Σ ‖(I₉ − K_ij) x‖² = xᵀ (2N·I₉ − (S + Sᵀ)) x,      S = Σ K_ij,
// so the minimiser over ‖x‖ = 1 is the eigenvector of the LARGEST eigenvalue of the symmetric
// 9×9 matrix S + Sᵀ (only the sum S is accumulated, O(81) per motion). Its sign and scale are
// fixed by det > 0 and the nearest rotation (kronecker.h RotationFromSignFreeVec). Noise-free the
// top eigenvalue is 2N; it is unique iff two motions have non-parallel rotation axes.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "hecal/handeye/motion.h"

namespace hecal::handeye {

// Relative gap (λ₉ − λ₈) / (2N) of the two largest eigenvalues of S + Sᵀ below which the
// rotation is not determined (parallel rotation axes, pure translations).
inline constexpr double kSignFreeRotationMinGap = 1e-10;

// Throws DegenerateError when motions is empty or the top eigenvalue is not separated.
Eigen::Matrix3d SignFreeRotation(const std::vector<Motion>& motions);

// The unit quaternions a of R_A and b of R_B of a motion, with b's sign chosen so that
// a · (q_X b q̄_X) ≥ 0 for the given estimate R_X (see the file comment).
struct AlignedQuaternions {
  Eigen::Quaterniond a;
  Eigen::Quaterniond b;
};
AlignedQuaternions AlignQuaternions(const Motion& motion, const Eigen::Matrix3d& R_X);

}  // namespace hecal::handeye
