// Test support for the hand-eye tests: an exact motion pair of a known hand-eye pose X.
#pragma once

#include <random>

#include "hecal/geometry/so3.h"
#include "hecal/geometry/types.h"
#include "hecal/handeye/motion.h"
#include "testing/random_poses.h"

namespace hecal::handeye {

// The noise-free motion pair (A = X B X⁻¹, B) of stations 0 and 1 whose camera motion B rotates
// by `rotation_vector` and has a random translation.
inline Motion MotionFor(const Pose& X, const Eigen::Vector3d& rotation_vector,
                        std::mt19937_64& rng) {
  const Pose B = MakePose(so3::Exp(rotation_vector), testing::RandomPose(rng).translation());
  return {X * B * X.inverse(), B, 0, 1};
}

}  // namespace hecal::handeye
