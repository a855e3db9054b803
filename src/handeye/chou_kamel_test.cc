#include "hecal/handeye/chou_kamel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

#include "handeye/handeye_test_util.h"
#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/so3.h"
#include "testing/handeye_solver_suite.h"
#include "testing/scene.h"

namespace hecal::handeye {
namespace {

// Unit axes weigh every motion equally, so motions that barely rotate — their axes are noise —
// must not enter: with 30 noisy motions of 0.05°–0.5° (axes essentially random) next to 10 good
// ones, the estimate stays at the accuracy of the good ones.
TEST(ChouKamel, NearZeroRotationsDoNotEnterTheUnitAxisSystem) {
  const testing::PoseNoise noise{0.05 * kRadiansPerDegree, 0.0};
  std::mt19937_64 rng(51);
  double worst_good = 0.0, worst_all = 0.0;
  for (int trial = 0; trial < 20; ++trial) {
    const Pose X = testing::RandomPose(rng, 0.1);
    std::vector<Motion> motions;
    hecal::UniformRealDistribution large(0.5, 3.0),
        small(0.05 * kRadiansPerDegree, 0.5 * kRadiansPerDegree);
    for (int k = 0; k < 10; ++k) {
      const Eigen::Vector3d axis = testing::RandomUnitVector(rng);  // drawn before the angle
      motions.push_back(MotionFor(X, large(rng) * axis, rng));
    }
    for (Motion& m : motions) m.A = testing::AddPoseNoise(m.A, noise, rng);
    worst_good = std::max(worst_good, testing::Error(SolveChouKamel(motions), X).rotation);
    for (int k = 0; k < 30; ++k) {
      const Eigen::Vector3d axis = testing::RandomUnitVector(rng);
      Motion m = MotionFor(X, small(rng) * axis, rng);
      m.A = testing::AddPoseNoise(m.A, noise, rng);
      motions.push_back(m);
    }
    worst_all = std::max(worst_all, testing::Error(SolveChouKamel(motions), X).rotation);
  }
  std::printf("worst rotation error: %.3f deg from 10 good motions, %.3f deg with 30 tiny ones\n",
              worst_good / kRadiansPerDegree, worst_all / kRadiansPerDegree);
  EXPECT_LT(worst_all, 1.5 * worst_good);
}

// When the large motions alone do not determine q (their axes are parallel), the solver falls
// back to every motion that rotates by more than kMinRotation.
TEST(ChouKamel, FallsBackToSmallerMotionsWhenTheLargeOnesShareAnAxis) {
  std::mt19937_64 rng(52);
  const Pose X = testing::RandomPose(rng, 0.1);
  const Eigen::Vector3d z = testing::RandomUnitVector(rng);
  std::vector<Motion> motions;
  for (double angle : {1.0, 2.0, 3.0}) motions.push_back(MotionFor(X, angle * z, rng));
  for (int k = 0; k < 2; ++k) {  // 0.05 rad < 10% of 3 rad
    motions.push_back(MotionFor(X, 0.05 * testing::RandomUnitVector(rng), rng));
  }
  testing::ExpectPoseNear(SolveChouKamel(motions), X, 1e-9, "X");
  motions.resize(3);
  EXPECT_THROW(SolveChouKamel(motions), DegenerateError);
}

}  // namespace
}  // namespace hecal::handeye
