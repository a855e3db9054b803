// The re-check at the polished X against the scene's truth: correct matches a previous stage
// removed come back, wrong matches it kept go, and the polished X lands within its covariance.
#include "hecal/estimation/epipolar_polish.h"

#include <gtest/gtest.h>

#include "hecal/geometry/se3.h"
#include "testing/epipolar_scenes.h"

namespace hecal::estimation {
namespace {

TEST(PolishAndRecheck, ReadmitsCorrectAndRemovesWrongMatches) {
  testing::EpipolarSceneSpec spec;
  spec.motions = 3;
  spec.pairs = 40;
  spec.pixel_sigma = 0.5;
  spec.wrong_fraction = 0.1;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 44);
  // A previous stage's guess: every wrong match of the first motion kept, the first five correct
  // matches of every motion removed, the other wrong matches removed.
  global::EpipolarProblem guess = scene.problem;
  int wrong_kept = 0;
  for (std::size_t m = 0; m < guess.motions.size(); ++m) {
    std::vector<global::BearingPair> kept;
    int correct_seen = 0;
    for (const global::BearingPair& pair : scene.problem.motions[m].pairs) {
      const bool wrong = scene.wrong[m][pair.id];
      if (wrong ? m == 0 : ++correct_seen > 5) kept.push_back(pair);
      wrong_kept += wrong && m == 0;
    }
    guess.motions[m].pairs = kept;
  }
  ASSERT_GT(wrong_kept, 0);
  const double sigma = spec.pixel_sigma / spec.focal;
  const RecheckedPolish result = PolishAndRecheck(scene.problem, guess, scene.X, sigma);
  int wrong_total = 0;
  for (const auto& motion : scene.wrong) {
    for (bool w : motion) wrong_total += w;
  }
  int wrong_removed = 0;
  for (const auto& [motion, id] : result.removed) {
    EXPECT_TRUE(scene.wrong[motion][id]) << "a correct match removed: " << motion << ", " << id;
    wrong_removed += scene.wrong[motion][id];
  }
  // A wrong match whose ray happens to lie near its epipolar plane may stay (harmless).
  EXPECT_GE(wrong_removed, wrong_total - 2);
  const Vector6d error = se3::Log(result.polish.X.inverse() * scene.X);
  EXPECT_LT(error.dot(result.polish.covariance.inverse() * error), 22.46);  // χ²₆ 99.9%
}

TEST(PolishAndRecheck, KeepsEveryPairOfANoiseFreeScene) {
  testing::EpipolarSceneSpec spec;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 9);
  const RecheckedPolish result = PolishAndRecheck(scene.problem, scene.problem, scene.X);
  EXPECT_TRUE(result.removed.empty());
  EXPECT_LT(testing::RotationError(result.polish.X, scene.X), 1e-9);
}

}  // namespace
}  // namespace hecal::estimation
