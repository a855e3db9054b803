#include "hecal/geometry/rotation.h"

#include <algorithm>
#include <cmath>

namespace hecal {

Eigen::Quaterniond CanonicalQuaternion(const Eigen::Quaterniond& q) {
  const double components[4] = {q.w(), q.x(), q.y(), q.z()};
  for (double c : components) {
    if (c > 0.0) return q;
    if (c < 0.0) return Eigen::Quaterniond(-q.w(), -q.x(), -q.y(), -q.z());
  }
  return q;
}

Eigen::Quaterniond QuaternionFromMatrix(const Eigen::Matrix3d& R) {
  // Shepperd (1978): pivot on the largest of 4w², 4x², 4y², 4z² so the division is by the
  // largest component and no precision is lost anywhere on SO(3).
  const double trace = R.trace();
  const double pivots[4] = {trace, R(0, 0), R(1, 1), R(2, 2)};
  const int k = static_cast<int>(std::max_element(pivots, pivots + 4) - pivots);
  double w, x, y, z;
  if (k == 0) {
    const double s = 2.0 * std::sqrt(1.0 + trace);  // 4w
    w = 0.25 * s;
    x = (R(2, 1) - R(1, 2)) / s;
    y = (R(0, 2) - R(2, 0)) / s;
    z = (R(1, 0) - R(0, 1)) / s;
  } else if (k == 1) {
    const double s = 2.0 * std::sqrt(1.0 + R(0, 0) - R(1, 1) - R(2, 2));  // 4x
    w = (R(2, 1) - R(1, 2)) / s;
    x = 0.25 * s;
    y = (R(0, 1) + R(1, 0)) / s;
    z = (R(0, 2) + R(2, 0)) / s;
  } else if (k == 2) {
    const double s = 2.0 * std::sqrt(1.0 - R(0, 0) + R(1, 1) - R(2, 2));  // 4y
    w = (R(0, 2) - R(2, 0)) / s;
    x = (R(0, 1) + R(1, 0)) / s;
    y = 0.25 * s;
    z = (R(1, 2) + R(2, 1)) / s;
  } else {
    const double s = 2.0 * std::sqrt(1.0 - R(0, 0) - R(1, 1) + R(2, 2));  // 4z
    w = (R(1, 0) - R(0, 1)) / s;
    x = (R(0, 2) + R(2, 0)) / s;
    y = (R(1, 2) + R(2, 1)) / s;
    z = 0.25 * s;
  }
  Eigen::Quaterniond q(w, x, y, z);
  q.normalize();
  return CanonicalQuaternion(q);
}

Eigen::Matrix3d MatrixFromQuaternion(const Eigen::Quaterniond& q) {
  return q.normalized().toRotationMatrix();
}

Eigen::Quaterniond QuaternionFromRotationVector(const Eigen::Vector3d& omega) {
  const double theta = omega.norm();
  const double half = 0.5 * theta;
  // sin(θ/2)/θ with its Taylor series ½ − θ²/48 + θ⁴/3840 below 1e-4 (error < 1e-20).
  const double k = theta < 1e-4 ? 0.5 - theta * theta / 48.0 : std::sin(half) / theta;
  return Eigen::Quaterniond(std::cos(half), k * omega.x(), k * omega.y(), k * omega.z());
}

Eigen::Vector3d RotationVectorFromQuaternion(const Eigen::Quaterniond& q_in) {
  const Eigen::Quaterniond q = CanonicalQuaternion(q_in.normalized());
  const Eigen::Vector3d v = q.vec();
  const double s = v.norm();  // sin(θ/2)
  const double w = q.w();     // cos(θ/2) ≥ 0
  // θ = 2 atan2(s, w) is accurate at both ends; ω = θ/s · v, with θ/s → 2/w (1 − s²/(3w²)) as
  // s → 0 (w → 1 there, so no division by a small number).
  double scale;
  if (s < 1e-8) {
    scale = 2.0 / w * (1.0 - s * s / (3.0 * w * w));
  } else {
    scale = 2.0 * std::atan2(s, w) / s;
  }
  Eigen::Vector3d omega = scale * v;
  // At exactly π (w == 0), ±ω are the same rotation: make the largest component positive.
  if (w == 0.0) {
    Eigen::Index i;
    omega.cwiseAbs().maxCoeff(&i);
    if (omega(i) < 0.0) omega = -omega;
  }
  return omega;
}

AxisAngle AxisAngleFromMatrix(const Eigen::Matrix3d& R) {
  const Eigen::Quaterniond q = QuaternionFromMatrix(R);
  const double s = q.vec().norm();
  AxisAngle result;
  if (s == 0.0) return result;  // identity: axis x, angle 0
  result.angle = 2.0 * std::atan2(s, q.w());
  result.axis = q.vec() / s;
  if (q.w() == 0.0) {  // θ = π: same deterministic sign as the rotation vector
    Eigen::Index i;
    result.axis.cwiseAbs().maxCoeff(&i);
    if (result.axis(i) < 0.0) result.axis = -result.axis;
  }
  return result;
}

Eigen::Matrix3d MatrixFromAxisAngle(const AxisAngle& axis_angle) {
  return QuaternionFromRotationVector(axis_angle.axis.normalized() * axis_angle.angle)
      .toRotationMatrix();
}

Eigen::Vector3d TsaiRodriguesFromMatrix(const Eigen::Matrix3d& R) {
  // 2 sin(θ/2) n is exactly twice the vector part of the canonical quaternion.
  return 2.0 * QuaternionFromMatrix(R).vec();
}

Eigen::Matrix3d MatrixFromTsaiRodrigues(const Eigen::Vector3d& P) {
  const Eigen::Vector3d v = 0.5 * P;  // sin(θ/2) n
  const double w = std::sqrt(std::max(0.0, 1.0 - v.squaredNorm()));
  return Eigen::Quaterniond(w, v.x(), v.y(), v.z()).normalized().toRotationMatrix();
}

}  // namespace hecal
