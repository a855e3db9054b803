#include "hecal/estimation/loop_residual.h"

#include "hecal/geometry/se3.h"

namespace hecal::estimation {

Vector6d LoopResidual(const Pose& A, const Pose& B, const Pose& X, const Pose& Z,
                      Matrix6x12d* jacobian) {
  const Pose E = Z.inverse() * A * X * B;
  const Vector6d r = se3::Log(E);
  if (jacobian != nullptr) {
    const Matrix6d Jr_inverse = se3::RightJacobianInverse(r);
    jacobian->leftCols<6>() = Jr_inverse * se3::Adjoint(B.inverse());
    jacobian->rightCols<6>() = -Jr_inverse * se3::Adjoint(E.inverse());
  }
  return r;
}

LoopCost::LoopCost(const Pose& A, const Pose& B, const Matrix6d& whitening)
    : A_(A), B_(B), whitening_(whitening) {}

ceres::CostFunction* LoopCost::Create(const Pose& A, const Pose& B, const Matrix6d& whitening) {
  return new LoopCost(A, B, whitening);
}

bool LoopCost::Evaluate(double const* const* parameters, double* residuals,
                        double** jacobians) const {
  const Pose X = PoseFromParameters(parameters[0]);
  const Pose Z = PoseFromParameters(parameters[1]);
  const bool want_jacobians =
      jacobians != nullptr && (jacobians[0] != nullptr || jacobians[1] != nullptr);
  Matrix6x12d J;
  const Vector6d r = LoopResidual(A_, B_, X, Z, want_jacobians ? &J : nullptr);
  Eigen::Map<Vector6d> residual_out(residuals);
  residual_out = whitening_ * r;
  if (!want_jacobians) return true;
  using AmbientJacobian = Eigen::Matrix<double, 6, kPoseAmbientSize, Eigen::RowMajor>;
  for (int block = 0; block < 2; ++block) {
    if (jacobians[block] == nullptr) continue;
    Eigen::Map<AmbientJacobian> ambient(jacobians[block]);
    ambient.leftCols<6>() = whitening_ * J.middleCols<6>(6 * block);
    ambient.col(6).setZero();
  }
  return true;
}

}  // namespace hecal::estimation
