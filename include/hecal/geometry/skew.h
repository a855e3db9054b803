// Skew-symmetric ("hat") matrix of a 3-vector and its inverse ("vee").
// Skew(a) · b = a × b. The thesis' EigenUtils `skew` (docs/handeye-methods.md#the-thesis-pipeline).
#pragma once

#include <Eigen/Core>

namespace hecal {

inline Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d S;
  S << 0.0, -v.z(), v.y(),  //
      v.z(), 0.0, -v.x(),   //
      -v.y(), v.x(), 0.0;
  return S;
}

// Inverse of Skew for a skew-symmetric matrix; for a general matrix it returns the vee of its
// antisymmetric part (S − Sᵀ)/2, which is what log maps need.
inline Eigen::Vector3d Vee(const Eigen::Matrix3d& S) {
  return 0.5 * Eigen::Vector3d(S(2, 1) - S(1, 2), S(0, 2) - S(2, 0), S(1, 0) - S(0, 1));
}

}  // namespace hecal
