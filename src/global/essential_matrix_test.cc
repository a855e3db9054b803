// The eight-point E and the rotation taken from it against the true camera motion of synthetic
// scenes; the Sampson angle against a known perpendicular distance.
#include "hecal/global/essential_matrix.h"

#include <gtest/gtest.h>

#include "testing/epipolar_scenes.h"

namespace hecal::global {
namespace {

TEST(RotationFromEssential, GivesTheTrueCameraRotationOfEveryMotion) {
  testing::EpipolarSceneSpec spec;
  spec.motions = 4;
  spec.pairs = 30;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 12);
  for (const EpipolarMotion& motion : scene.problem.motions) {
    const Pose A = CameraMotion(scene.X, motion.hand);
    const auto R = RotationFromEssential(motion.pairs);
    ASSERT_TRUE(R.has_value());
    EXPECT_LT((*R - A.linear()).norm(), 1e-8);
  }
}

TEST(RotationFromEssential, NeedsEightPairs) {
  testing::EpipolarSceneSpec spec;
  spec.pairs = 7;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 2);
  EXPECT_FALSE(RotationFromEssential(scene.problem.motions[0].pairs).has_value());
}

TEST(SampsonError, IsTheAngleOfARayTurnedOutOfItsEpipolarPlane) {
  // Pure translation along x: E = [e_x]×; epipolar planes contain the x axis. A first ray in the
  // x–z plane and a second ray turned by 0.01 rad out of it, about x: both rays perpendicular to
  // x, so the Sampson angle is the turn split over the two rays, 0.01 / √2 (first order).
  Eigen::Matrix3d E;
  E << 0, 0, 0, 0, 0, -1, 0, 1, 0;
  BearingPair pair;
  pair.first = Eigen::Vector3d::UnitZ();
  pair.second = Eigen::Vector3d(0, std::sin(0.01), std::cos(0.01));
  EXPECT_NEAR(SampsonError(E, pair), 0.01 / std::sqrt(2.0), 1e-6);
  pair.second = Eigen::Vector3d(0.3, 0, 1).normalized();
  EXPECT_NEAR(SampsonError(E, pair), 0.0, 1e-15);
}

}  // namespace
}  // namespace hecal::global
