#include "hecal/geometry/se3.h"

#include <cmath>

#include "hecal/geometry/skew.h"
#include "hecal/geometry/so3.h"

namespace hecal::se3 {
namespace {

// Barfoot (2017) eq. 7.86: the coupling block Q(ω, v) of the SE(3) left Jacobian,
//   Q = ½V + c1 (WV + VW + WVW) + c2 (WWV + VWW − 3 WVW) + c3 (WVWW + WWVW),
// with W = [ω]×, V = [v]×. The coefficients use Taylor series for small θ, where the closed
// forms cancel catastrophically (c3's numerator is θ⁵/60 built from O(θ) terms).
Eigen::Matrix3d LeftJacobianCoupling(const Eigen::Vector3d& omega, const Eigen::Vector3d& v) {
  const double theta = omega.norm();
  const double t2 = theta * theta;
  double c1, c2, c3;
  if (theta < 0.1) {
    const double t4 = t2 * t2;
    c1 = 1.0 / 6.0 - t2 / 120.0 + t4 / 5040.0 - t4 * t2 / 362880.0;
    c2 = 1.0 / 24.0 - t2 / 720.0 + t4 / 40320.0 - t4 * t2 / 3628800.0;
    c3 = 1.0 / 120.0 - t2 / 2520.0 + t4 / 120960.0 - t4 * t2 / 9979200.0;
  } else {
    const double s = std::sin(theta);
    const double c = std::cos(theta);
    const double s_half = std::sin(0.5 * theta);
    c1 = (theta - s) / (t2 * theta);
    // θ² − 2(1 − cos θ) with 1 − cos θ = 2 sin²(θ/2): computing 2 cos θ − 2 directly costs an
    // absolute ε in a numerator of size θ⁴/12 (relative error 1.4e-11 at θ = 0.1).
    c2 = (t2 - 4.0 * s_half * s_half) / (2.0 * t2 * t2);
    c3 = (2.0 * theta - 3.0 * s + theta * c) / (2.0 * t2 * t2 * theta);
  }
  const Eigen::Matrix3d W = Skew(omega);
  const Eigen::Matrix3d V = Skew(v);
  const Eigen::Matrix3d WV = W * V;
  const Eigen::Matrix3d VW = V * W;
  const Eigen::Matrix3d WVW = WV * W;
  return 0.5 * V + c1 * (WV + VW + WVW) + c2 * (W * WV + VW * W - 3.0 * WVW) +
         c3 * (WVW * W + W * WVW);
}

}  // namespace

Pose Exp(const Vector6d& xi) {
  const Eigen::Vector3d omega = xi.head<3>();
  return MakePose(so3::Exp(omega), so3::LeftJacobian(omega) * xi.tail<3>());
}

Vector6d Log(const Pose& T) {
  const Eigen::Vector3d omega = so3::Log(T.linear());
  Vector6d xi;
  xi << omega, so3::LeftJacobianInverse(omega) * T.translation();
  return xi;
}

Matrix6d Adjoint(const Pose& T) {
  const Eigen::Matrix3d R = T.linear();
  Matrix6d A = Matrix6d::Zero();
  A.topLeftCorner<3, 3>() = R;
  A.bottomLeftCorner<3, 3>() = Skew(T.translation()) * R;
  A.bottomRightCorner<3, 3>() = R;
  return A;
}

Matrix6d LeftJacobian(const Vector6d& xi) {
  const Eigen::Vector3d omega = xi.head<3>();
  const Eigen::Matrix3d J = so3::LeftJacobian(omega);
  Matrix6d result = Matrix6d::Zero();
  result.topLeftCorner<3, 3>() = J;
  result.bottomRightCorner<3, 3>() = J;
  result.bottomLeftCorner<3, 3>() = LeftJacobianCoupling(omega, xi.tail<3>());
  return result;
}

Matrix6d LeftJacobianInverse(const Vector6d& xi) {
  const Eigen::Vector3d omega = xi.head<3>();
  const Eigen::Matrix3d J_inv = so3::LeftJacobianInverse(omega);
  Matrix6d result = Matrix6d::Zero();
  result.topLeftCorner<3, 3>() = J_inv;
  result.bottomRightCorner<3, 3>() = J_inv;
  result.bottomLeftCorner<3, 3>() = -J_inv * LeftJacobianCoupling(omega, xi.tail<3>()) * J_inv;
  return result;
}

Matrix6d RightJacobian(const Vector6d& xi) {
  return LeftJacobian(-xi);
}

Matrix6d RightJacobianInverse(const Vector6d& xi) {
  return LeftJacobianInverse(-xi);
}

Pose Interpolate(const Pose& T0, const Pose& T1, double s) {
  return T0 * Exp(s * Log(T0.inverse() * T1));
}

}  // namespace hecal::se3
