#include "hecal/geometry/quaternion_matrices.h"

namespace hecal {

Eigen::Matrix4d QuaternionLeftMatrix(const Eigen::Vector4d& r) {
  Eigen::Matrix4d Q;
  Q << r(0), -r(1), -r(2), -r(3),  //
      r(1), r(0), -r(3), r(2),     //
      r(2), r(3), r(0), -r(1),     //
      r(3), -r(2), r(1), r(0);
  return Q;
}

Eigen::Matrix4d QuaternionRightMatrix(const Eigen::Vector4d& r) {
  Eigen::Matrix4d W;
  W << r(0), -r(1), -r(2), -r(3),  //
      r(1), r(0), r(3), -r(2),     //
      r(2), -r(3), r(0), r(1),     //
      r(3), r(2), -r(1), r(0);
  return W;
}

}  // namespace hecal
