// Kronecker-product building blocks shared by the linear rotation solvers: Andreff (AX = XB),
// Shah and Li (AX = ZB), and the sign-free rotation estimate of rotation_init.h.
//
// vec() stacks the COLUMNS of a 3×3 matrix (Eigen's storage order), so for 3×3 matrices
//        vec(P · M · Q) = (Qᵀ ⊗ P) · vec(M).                                          (K1)
// Two consequences used by every caller:
//  - a rotation equation R_A · R_X = R_X · R_B (motions) is R_A R_X R_Bᵀ = R_X, i.e.
//        (R_B ⊗ R_A) vec(R_X) = vec(R_X);                                             (K2)
//  - a rotation equation R_Z = R_A · R_X · R_B (absolute poses, problem.h) is
//        (R_Bᵀ ⊗ R_A) vec(R_X) = vec(R_Z).                                            (K3)
// The Kronecker product of two rotations is a 9×9 orthogonal matrix, so the least-squares
// normal matrices of (K2) and (K3) reduce to sums of such products; callers accumulate the 9×9
// sum Σ P_i ⊗ Q_i with AddKronecker (81 multiply–adds, no allocation) and never build the
// 9n-row system.
#pragma once

#include <Eigen/Core>

namespace hecal::handeye {

using Matrix9d = Eigen::Matrix<double, 9, 9>;
using Vector9d = Eigen::Matrix<double, 9, 1>;

// *sum += P ⊗ Q  (block (r, c) of the product is P(r, c) · Q).
void AddKronecker(const Eigen::Matrix3d& P, const Eigen::Matrix3d& Q, Matrix9d* sum);

// Column-major vec and its inverse.
Vector9d Vec(const Eigen::Matrix3d& M);
Eigen::Matrix3d Unvec(const Vector9d& v);

// The rotation nearest to the 3×3 matrix vec⁻¹(v) after fixing the sign of a null-space or
// singular vector: v and −v are equally valid solutions of a homogeneous system, and only the one
// with det(vec⁻¹(v)) > 0 is (a multiple of) a rotation. The scale of v does not matter.
Eigen::Matrix3d RotationFromSignFreeVec(const Vector9d& v);

}  // namespace hecal::handeye
