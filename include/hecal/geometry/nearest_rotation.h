// The rotation nearest to a 3×3 matrix in the Frobenius norm: argmin_R ‖R − M‖_F, R ∈ SO(3).
//
// Two forms that must agree (tested):
//  - NearestRotationSvd: polar projection U · diag(1, 1, det(U Vᵀ)) · Vᵀ from M = U Σ Vᵀ.
//  - NearestRotationQuaternion: the linear pose paper (docs/pose-from-points.md#the-linear-method,
//    after Horn / Faugeras): the unit quaternion q minimising Σ_i ‖m_i * q − q * e_i‖² over the
//    columns m_i of M and e_i of I is the eigenvector of the smallest eigenvalue of D = Σ_i D_iᵀ
//    D_i, with
//      D_i = [ 0          (e_i − m_i)ᵀ   ]
//            [ m_i − e_i  [m_i + e_i]×   ]        (4×4, quaternion order w, x, y, z)
//    and R is the rotation of q (the linear pose paper eq. 28).
// Both are defined for every M; for rank-deficient M the answer is not unique and either form
// returns one of the minimisers.
#pragma once

#include <Eigen/Core>

namespace hecal {

Eigen::Matrix3d NearestRotationSvd(const Eigen::Matrix3d& M);
Eigen::Matrix3d NearestRotationQuaternion(const Eigen::Matrix3d& M);

}  // namespace hecal
