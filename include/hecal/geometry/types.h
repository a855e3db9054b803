// Fixed-size Eigen types used across hecal. Poses are Eigen::Isometry3d named T_a_b
// (docs/conventions.md): the pose of frame b in frame a, x_a = T_a_b · x_b. Lengths are metres,
// angles radians.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hecal {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Pose = Eigen::Isometry3d;

// Builds a pose from a rotation matrix and a translation (no orthonormality check).
inline Pose MakePose(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  Pose T = Pose::Identity();
  T.linear() = R;
  T.translation() = t;
  return T;
}

}  // namespace hecal
