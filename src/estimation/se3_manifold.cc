#include "hecal/estimation/se3_manifold.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "hecal/geometry/se3.h"

namespace hecal::estimation {

void PoseToParameters(const Pose& T, double* parameters) {
  const Eigen::Quaterniond q(T.linear());
  Eigen::Map<Eigen::Vector4d> quaternion(parameters);
  Eigen::Map<Eigen::Vector3d> translation(parameters + 4);
  quaternion = q.coeffs();  // x, y, z, w
  translation = T.translation();
}

Pose PoseFromParameters(const double* parameters) {
  const Eigen::Quaterniond q{Eigen::Vector4d(Eigen::Map<const Eigen::Vector4d>(parameters))};
  return MakePose(q.normalized().toRotationMatrix(),
                  Eigen::Map<const Eigen::Vector3d>(parameters + 4));
}

bool Se3RightManifold::Plus(const double* x, const double* delta, double* x_plus_delta) const {
  const Pose T = PoseFromParameters(x) * se3::Exp(Eigen::Map<const Vector6d>(delta));
  PoseToParameters(T, x_plus_delta);
  return true;
}

bool Se3RightManifold::PlusJacobian(const double* /*x*/, double* jacobian) const {
  Eigen::Map<Eigen::Matrix<double, kPoseAmbientSize, kPoseTangentSize, Eigen::RowMajor>> J(
      jacobian);
  J.setZero();
  J.topRows<kPoseTangentSize>().setIdentity();
  return true;
}

bool Se3RightManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  Eigen::Map<Vector6d> difference(y_minus_x);
  difference = se3::Log(PoseFromParameters(x).inverse() * PoseFromParameters(y));
  return true;
}

bool Se3RightManifold::MinusJacobian(const double* /*x*/, double* jacobian) const {
  Eigen::Map<Eigen::Matrix<double, kPoseTangentSize, kPoseAmbientSize, Eigen::RowMajor>> J(
      jacobian);
  J.setZero();
  J.leftCols<kPoseTangentSize>().setIdentity();
  return true;
}

}  // namespace hecal::estimation
