#include "hecal/estimation/loop_residual.h"

#include "hecal/geometry/se3.h"
#include "hecal/geometry/skew.h"

namespace hecal::estimation {
namespace {

// Jr⁻¹ · Ad(T) by 3 × 3 blocks. Both factors are block lower-triangular with equal diagonal
// blocks, Jr⁻¹ = [[P, 0], [S, P]] (se3.h) and Ad(T) = [[R, 0], [t^ R, R]], so the product is
// [[P R, 0], [(S + P t^) R, P R]]: 81 multiplications where the 6 × 6 product took 216 (the
// Jacobian is formed at every station of every Gauss–Newton step of ml).
Matrix6d TimesAdjoint(const Matrix6d& Jr_inverse, const Pose& T) {
  const Eigen::Matrix3d P = Jr_inverse.topLeftCorner<3, 3>();
  const Eigen::Matrix3d PR = P * T.linear();
  Matrix6d product;
  product.topLeftCorner<3, 3>() = PR;
  product.topRightCorner<3, 3>().setZero();
  product.bottomLeftCorner<3, 3>() =
      (Jr_inverse.bottomLeftCorner<3, 3>() + P * Skew(T.translation())) * T.linear();
  product.bottomRightCorner<3, 3>() = PR;
  return product;
}

}  // namespace

Vector6d LoopResidual(const Pose& A, const Pose& B, const Pose& X, const Pose& Z,
                      Matrix6x12d* jacobian) {
  const Pose E = Z.inverse() * A * X * B;
  const Vector6d r = se3::Log(E);
  if (jacobian != nullptr) {
    const Matrix6d Jr_inverse = se3::RightJacobianInverse(r);
    jacobian->leftCols<6>() = TimesAdjoint(Jr_inverse, B.inverse());
    jacobian->rightCols<6>() = -TimesAdjoint(Jr_inverse, E.inverse());
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
