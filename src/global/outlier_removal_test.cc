// Wrong matches among 0.5 px noisy pairs are removed (precision and recall against the scene's
// truth), and X lands within the L2 polish's covariance of the truth.
#include "hecal/global/outlier_removal.h"

#include <gtest/gtest.h>

#include <set>

#include "hecal/estimation/epipolar_polish.h"
#include "hecal/geometry/se3.h"
#include "testing/epipolar_scenes.h"

namespace hecal::global {
namespace {

TEST(SolveGlobalRobust, RemovesWrongMatchesWithHighPrecisionAndRecall) {
  testing::EpipolarSceneSpec spec;
  spec.motions = 3;
  spec.pairs = 40;
  spec.pixel_sigma = 0.5;
  spec.wrong_fraction = 0.1;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 31);
  SearchOptions search;
  search.epsilon = 3e-3;  // the decision rounds only: closing a noisy gap is slow
  search.translation_bound = 1.0;
  OutlierOptions options;
  options.threshold = 4.0 * 0.5 / spec.focal * std::sqrt(2.0);
  const RobustGlobalSolution robust = SolveGlobalRobust(scene.problem, search, options);
  int true_positive = 0, wrong_total = 0;
  for (std::size_t m = 0; m < scene.wrong.size(); ++m) {
    for (bool w : scene.wrong[m]) wrong_total += w;
  }
  for (const RemovedPair& removed : robust.removed) {
    true_positive += scene.wrong[removed.motion][removed.id];
  }
  const double precision = double(true_positive) / std::max<std::size_t>(1, robust.removed.size());
  const double recall = double(true_positive) / wrong_total;
  std::printf("wrong %d removed %zu precision %.3f recall %.3f rounds %d upper %.3g\n", wrong_total,
              robust.removed.size(), precision, recall, robust.rounds,
              robust.solution.certificate.upper);
  ASSERT_GT(wrong_total, 5);
  EXPECT_GE(precision, 0.8);
  // A wrong match whose point happens to lie near its epipolar plane is harmless and may stay.
  EXPECT_GE(recall, 0.8);
  EXPECT_LE(robust.solution.certificate.upper, options.threshold);
  // The L2 polish on the inliers lands within its covariance of the truth: NEES below the
  // chi-square(6) 99.9% point.
  const estimation::EpipolarPolish polish =
      estimation::PolishEpipolar(robust.inliers, robust.solution.X, spec.pixel_sigma / spec.focal);
  const Vector6d error = se3::Log(polish.X.inverse() * scene.X);
  const double nees = error.dot(polish.covariance.inverse() * error);
  std::printf("polish rotation error %.3g rad, nees %.2f\n",
              testing::RotationError(polish.X, scene.X), nees);
  EXPECT_LT(nees, 22.46);
}

TEST(PrefilterPairs, KeepsEveryPairOfANoiseFreeScene) {
  testing::EpipolarSceneSpec spec;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 4);
  std::vector<RemovedPair> removed;
  const EpipolarProblem kept = PrefilterPairs(scene.problem, OutlierOptions{}, &removed);
  EXPECT_TRUE(removed.empty());
  EXPECT_EQ(PairCount(kept), PairCount(scene.problem));
}

}  // namespace
}  // namespace hecal::global
