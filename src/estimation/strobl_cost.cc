#include "hecal/estimation/strobl_cost.h"

#include <cmath>

#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"

namespace hecal::estimation {

Vector9d StroblResidual(const Pose& A, const Pose& B, const Pose& X, const Pose& Z,
                        Matrix9x12d* jacobian) {
  const Pose M = A * X * B;
  const Pose Z_inverse = Z.inverse();
  const Pose E = Z_inverse * M;
  const Pose D = M * Z_inverse;
  const double half_root = std::sqrt(0.5);
  const Eigen::Vector3d omega = so3::Log(E.linear());
  Vector9d e;
  e << omega, half_root * E.translation(), half_root * D.translation();
  if (jacobian != nullptr) {
    const Matrix6d B_inverse = se3::Adjoint(B.inverse());
    const Matrix6d Gamma_E_X = B_inverse;
    const Matrix6d Gamma_E_Z = -se3::Adjoint(E.inverse());
    const Matrix6d Ad_Z = se3::Adjoint(Z);
    const Matrix6d Gamma_D_X = Ad_Z * B_inverse;
    const Matrix6d& Gamma_D_Z = Ad_Z;  // with a minus sign, below
    const Eigen::Matrix3d Jr_inverse = so3::RightJacobianInverse(omega);
    const Eigen::Matrix3d R_E = E.linear();
    const Eigen::Matrix3d R_D = D.linear();
    jacobian->block<3, 6>(0, 0) = Jr_inverse * Gamma_E_X.topRows<3>();
    jacobian->block<3, 6>(0, 6) = Jr_inverse * Gamma_E_Z.topRows<3>();
    jacobian->block<3, 6>(3, 0) = half_root * R_E * Gamma_E_X.bottomRows<3>();
    jacobian->block<3, 6>(3, 6) = half_root * R_E * Gamma_E_Z.bottomRows<3>();
    jacobian->block<3, 6>(6, 0) = half_root * R_D * Gamma_D_X.bottomRows<3>();
    jacobian->block<3, 6>(6, 6) = -half_root * R_D * Gamma_D_Z.bottomRows<3>();
  }
  return e;
}

StroblCost::StroblCost(const Pose& A, const Pose& B, double sigma_rotation,
                       double sigma_translation)
    : A_(A), B_(B) {
  weights_ << Eigen::Vector3d::Constant(1.0 / sigma_rotation),
      Eigen::Matrix<double, 6, 1>::Constant(1.0 / sigma_translation);
}

ceres::CostFunction* StroblCost::Create(const Pose& A, const Pose& B, double sigma_rotation,
                                        double sigma_translation) {
  return new StroblCost(A, B, sigma_rotation, sigma_translation);
}

bool StroblCost::Evaluate(double const* const* parameters, double* residuals,
                          double** jacobians) const {
  const Pose X = PoseFromParameters(parameters[0]);
  const Pose Z = PoseFromParameters(parameters[1]);
  const bool want_jacobians =
      jacobians != nullptr && (jacobians[0] != nullptr || jacobians[1] != nullptr);
  Matrix9x12d J;
  const Vector9d e = StroblResidual(A_, B_, X, Z, want_jacobians ? &J : nullptr);
  Eigen::Map<Vector9d> residual_out(residuals);
  residual_out = weights_.cwiseProduct(e);
  if (!want_jacobians) return true;
  using AmbientJacobian = Eigen::Matrix<double, 9, kPoseAmbientSize, Eigen::RowMajor>;
  for (int block = 0; block < 2; ++block) {
    if (jacobians[block] == nullptr) continue;
    Eigen::Map<AmbientJacobian> ambient(jacobians[block]);
    ambient.leftCols<6>() = weights_.asDiagonal() * J.middleCols<6>(6 * block);
    ambient.col(6).setZero();
  }
  return true;
}

}  // namespace hecal::estimation
