#include "hecal/handeye/kronecker.h"

#include <Eigen/LU>

#include "hecal/geometry/nearest_rotation.h"

namespace hecal::handeye {

void AddKronecker(const Eigen::Matrix3d& P, const Eigen::Matrix3d& Q, Matrix9d* sum) {
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      sum->block<3, 3>(3 * r, 3 * c) += P(r, c) * Q;
    }
  }
}

Vector9d Vec(const Eigen::Matrix3d& M) {
  return Eigen::Map<const Vector9d>(M.data());
}

Eigen::Matrix3d Unvec(const Vector9d& v) {
  return Eigen::Map<const Eigen::Matrix3d>(v.data());
}

Eigen::Matrix3d RotationFromSignFreeVec(const Vector9d& v) {
  const Eigen::Matrix3d M = Unvec(v);
  return NearestRotationSvd(M.determinant() < 0.0 ? Eigen::Matrix3d(-M) : M);
}

}  // namespace hecal::handeye
