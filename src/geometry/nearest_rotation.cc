// The rotation nearest to a 3×3 matrix in the Frobenius norm (see nearest_rotation.h).
//
// SVD form: for M = U Σ Vᵀ (σ1 ≥ σ2 ≥ σ3), argmax_R tr(Rᵀ M) over SO(3) is
// U diag(1, 1, det(U Vᵀ)) Vᵀ (Umeyama 1991, lemma; Horn, Hilden & Negahdaripour 1988).
//
// Quaternion form, the linear pose paper ("A simple algorithm for determining the position and the
// orientation of rigid bodies basing on visual information", Silesian Univ. of Technology;
// docs/pose-from-points.md; section 5, eqs. 27–32, after Horn 1987 / Faugeras): for a unit
// quaternion q, R(q) e = q * e * q̄, so
//   ‖m_i − R(q) e_i‖ = ‖m_i * q − q * e_i‖ = ‖D_i q‖,
//   D_i = Q(m_i) − W(e_i) = [ 0          (e_i − m_i)ᵀ ]
//                           [ m_i − e_i  [m_i + e_i]×  ]                      (eq. 31, 32)
// with Q, W the left/right product matrices of quaternion_matrices.h. Summing over the columns,
// ‖M − R(q)‖_F² = qᵀ D q with D = Σ D_iᵀ D_i (eq. 30), minimised on the unit sphere by the
// eigenvector of the smallest eigenvalue (eq. 29); R follows from q by eq. 28.
#include "hecal/geometry/nearest_rotation.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "hecal/geometry/skew.h"

namespace hecal {

Eigen::Matrix3d NearestRotationSvd(const Eigen::Matrix3d& M) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d& U = svd.matrixU();
  const Eigen::Matrix3d& V = svd.matrixV();
  // Flip the direction of the smallest singular value when U Vᵀ is a reflection.
  const double sign = (U * V.transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return U * Eigen::Vector3d(1.0, 1.0, sign).asDiagonal() * V.transpose();
}

Eigen::Matrix3d NearestRotationQuaternion(const Eigen::Matrix3d& M) {
  Eigen::Matrix4d D = Eigen::Matrix4d::Zero();
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d m = M.col(i);
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(i);
    Eigen::Matrix4d D_i;
    D_i(0, 0) = 0.0;
    D_i.block<1, 3>(0, 1) = (e - m).transpose();
    D_i.block<3, 1>(1, 0) = m - e;
    D_i.block<3, 3>(1, 1) = Skew(m + e);
    D.noalias() += D_i.transpose() * D_i;
  }
  // Eigenvalues come sorted in increasing order: column 0 belongs to the smallest.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(D);
  const Eigen::Vector4d q = eigen.eigenvectors().col(0);  // (w, x, y, z), unit
  return Eigen::Quaterniond(q(0), q(1), q(2), q(3)).normalized().toRotationMatrix();
}

}  // namespace hecal
