#include "hecal/geometry/so3.h"

#include <algorithm>
#include <cmath>

#include "hecal/geometry/rotation.h"
#include "hecal/geometry/skew.h"

namespace hecal::so3 {
namespace {

// Below this angle the Jacobian coefficients use Taylor series through θ⁴; the first omitted
// term is < 1e-17 there, while the closed forms would lose digits to cancellation.
constexpr double kSeriesAngle = 1e-2;

// b = (1 − cos θ)/θ²,  c = (θ − sin θ)/θ³  (coefficients of Jl = I + b K + c K², K = [ω]×).
void JacobianCoefficients(double theta, double* b, double* c) {
  const double t2 = theta * theta;
  if (theta < kSeriesAngle) {
    *b = 0.5 - t2 / 24.0 + t2 * t2 / 720.0;
    *c = 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0;
  } else {
    const double s = std::sin(0.5 * theta);
    *b = 2.0 * s * s / t2;  // 1 − cos θ = 2 sin²(θ/2), no cancellation
    *c = (theta - std::sin(theta)) / (t2 * theta);
  }
}

// e = 1/θ² − cot(θ/2)/(2θ)  (coefficient of Jl⁻¹ = I − ½ K + e K²); finite up to θ = π.
double InverseJacobianCoefficient(double theta) {
  const double t2 = theta * theta;
  if (theta < kSeriesAngle) return 1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30240.0;
  const double half = 0.5 * theta;
  return 1.0 / t2 - std::cos(half) / (2.0 * theta * std::sin(half));
}

}  // namespace

Eigen::Matrix3d Exp(const Eigen::Vector3d& omega) {
  // Through the quaternion: exactly orthonormal to rounding for every angle.
  return QuaternionFromRotationVector(omega).toRotationMatrix();
}

Eigen::Vector3d Log(const Eigen::Matrix3d& R) {
  return RotationVectorFromQuaternion(QuaternionFromMatrix(R));
}

Eigen::Matrix3d LeftJacobian(const Eigen::Vector3d& omega) {
  double b, c;
  JacobianCoefficients(omega.norm(), &b, &c);
  const Eigen::Matrix3d K = Skew(omega);
  return Eigen::Matrix3d::Identity() + b * K + c * K * K;
}

Eigen::Matrix3d RightJacobian(const Eigen::Vector3d& omega) {
  return LeftJacobian(-omega);
}

Eigen::Matrix3d LeftJacobianInverse(const Eigen::Vector3d& omega) {
  const double e = InverseJacobianCoefficient(omega.norm());
  const Eigen::Matrix3d K = Skew(omega);
  return Eigen::Matrix3d::Identity() - 0.5 * K + e * K * K;
}

Eigen::Matrix3d RightJacobianInverse(const Eigen::Vector3d& omega) {
  return LeftJacobianInverse(-omega);
}

Eigen::Matrix3d Interpolate(const Eigen::Matrix3d& R0, const Eigen::Matrix3d& R1, double s) {
  return R0 * Exp(s * Log(R0.transpose() * R1));
}

double Angle(const Eigen::Matrix3d& R) {
  const Eigen::Quaterniond q = QuaternionFromMatrix(R);
  return 2.0 * std::atan2(q.vec().norm(), std::abs(q.w()));
}

double Distance(const Eigen::Matrix3d& R_a, const Eigen::Matrix3d& R_b) {
  return Angle(R_a.transpose() * R_b);
}

double OrthonormalityError(const Eigen::Matrix3d& M) {
  const double gram = (M.transpose() * M - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  return std::max(gram, std::abs(M.determinant() - 1.0));
}

}  // namespace hecal::so3
