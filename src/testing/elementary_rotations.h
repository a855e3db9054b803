// Test support (not installed): elementary rotations from Eigen's AngleAxis — an independent
// definition for checking hecal's Euler conventions by composing them by hand.
#pragma once

#include <Eigen/Geometry>

namespace hecal::testing {

inline Eigen::Matrix3d Rx(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).matrix();
}
inline Eigen::Matrix3d Ry(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).matrix();
}
inline Eigen::Matrix3d Rz(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).matrix();
}

}  // namespace hecal::testing
