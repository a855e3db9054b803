// Test support for the pose tests: the rotation error of an estimated camera pose.
#pragma once

#include <Eigen/Geometry>

#include "hecal/geometry/types.h"

namespace hecal::pose {

// The angle of the rotation between the two poses' orientations, in radians.
inline double RotationError(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

}  // namespace hecal::pose
