// The local start against the truth of synthetic scenes: exact without noise, near the truth
// with pixel noise, none when every hand rotation shares one axis.
#include "hecal/global/local_start.h"

#include <gtest/gtest.h>

#include "testing/epipolar_scenes.h"

namespace hecal::global {
namespace {

TEST(LocalStart, RecoversXOfANoiseFreeSceneInBothSetups) {
  for (const auto setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    testing::EpipolarSceneSpec spec;
    spec.motions = 4;
    spec.pairs = 20;
    spec.setup = setup;
    const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 21);
    const auto X = LocalStart(scene.problem, 2.0);
    ASSERT_TRUE(X.has_value());
    EXPECT_LT(testing::RotationError(*X, scene.X), 1e-7);
    // The translation to the bisection's precision (30 halvings of π/2 in E).
    EXPECT_LT((X->translation() - scene.X.translation()).norm(), 1e-5);
    EXPECT_LT(MaxRayError(scene.problem, *X), 1e-7);
  }
}

TEST(LocalStart, LandsNearTheTruthWithPixelNoise) {
  testing::EpipolarSceneSpec spec;
  spec.motions = 6;
  spec.pairs = 40;
  spec.pixel_sigma = 0.5;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 5);
  const auto X = LocalStart(scene.problem, 2.0);
  ASSERT_TRUE(X.has_value());
  // 0.5 px at f = 1000 is 5e-4 rad per ray; a start, not an estimate: within ten times that
  // (0.6°) and 5 cm of the truth (the scene is 1 m deep, robot steps 0.3 m).
  EXPECT_LT(testing::RotationError(*X, scene.X), 1e-2);
  EXPECT_LT((X->translation() - scene.X.translation()).norm(), 0.05);
}

TEST(LocalStart, NoneFromOneMotion) {
  testing::EpipolarSceneSpec spec;
  spec.motions = 1;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 3);
  EXPECT_FALSE(LocalStart(scene.problem, 2.0).has_value());
}

}  // namespace
}  // namespace hecal::global
