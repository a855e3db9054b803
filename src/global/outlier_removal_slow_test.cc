// Wrong-match removal and the L2 polish's covariance over many trials (docs/global.md, "Measured"):
// 3 motions × 40 pairs, 0.5 px noise at f = 1000 px, 10% wrong matches, a new scene per trial.
// Reports the precision and recall of the removal (the L∞ removal, then the re-check at the
// polished X: estimation/epipolar_polish.h PolishAndRecheck) over all trials and the mean NEES of
// the polished X against the truth (χ²₆: mean 6). HECAL_GLOBAL_TRIALS sets the number of trials
// (default 100). Slow: about a second per trial on an idle core.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "hecal/estimation/epipolar_polish.h"
#include "hecal/geometry/se3.h"
#include "hecal/global/outlier_removal.h"
#include "testing/epipolar_scenes.h"

namespace hecal::global {
namespace {

TEST(SolveGlobalRobust, RemovesWrongMatchesAndTheCovarianceHoldsOverManyTrials) {
  const char* env = std::getenv("HECAL_GLOBAL_TRIALS");
  const int trials = env ? std::max(1, std::atoi(env)) : 100;
  testing::EpipolarSceneSpec spec;
  spec.motions = 3;
  spec.pairs = 40;
  spec.pixel_sigma = 0.5;
  spec.wrong_fraction = 0.1;
  OutlierOptions options;
  options.threshold = 4.0 * std::sqrt(2.0) * spec.pixel_sigma / spec.focal;
  SearchOptions search;
  // The removal's decisions only (is everything within the threshold?): closing a gap below the
  // noise takes minutes per trial; the polish, not the L∞ optimum, gives the final X.
  search.epsilon = options.threshold;
  search.translation_bound = 1.0;
  long wrong = 0, removed = 0, true_positive = 0, l_infinity_removed = 0, l_infinity_true = 0;
  double nees_sum = 0.0;
  int above_999 = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 1000 + trial);
    for (const std::vector<bool>& motion : scene.wrong) {
      for (bool w : motion) wrong += w;
    }
    const RobustGlobalSolution robust = SolveGlobalRobust(scene.problem, search, options);
    const Certificate& certificate = robust.solution.certificate;
    EXPECT_TRUE(certificate.certified)
        << "trial " << trial << ": [" << certificate.lower << ", " << certificate.upper << "], "
        << certificate.cubes << " cubes";
    const estimation::RecheckedPolish rechecked = estimation::PolishAndRecheck(
        scene.problem, robust.inliers, robust.solution.X, spec.pixel_sigma / spec.focal);
    const estimation::EpipolarPolish& polish = rechecked.polish;
    l_infinity_removed += long(robust.removed.size());
    for (const RemovedPair& pair : robust.removed) {
      l_infinity_true += scene.wrong[pair.motion][pair.id];
    }
    removed += long(rechecked.removed.size());
    for (const auto& [motion, id] : rechecked.removed) true_positive += scene.wrong[motion][id];
    const Vector6d error = se3::Log(polish.X.inverse() * scene.X);
    const double nees = error.dot(polish.covariance.inverse() * error);
    nees_sum += nees;
    above_999 += nees > 22.46;  // χ²₆ 99.9%
  }
  const double precision = double(true_positive) / double(std::max(1L, removed));
  const double recall = double(true_positive) / double(std::max(1L, wrong));
  const double mean_nees = nees_sum / trials;
  std::printf(
      "trials %d: wrong %ld, removed %ld, precision %.3f, recall %.3f, mean NEES %.2f, "
      "above the 99.9%% point %d (before the re-check: removed %ld, precision %.3f, recall "
      "%.3f)\n",
      trials, wrong, removed, precision, recall, mean_nees, above_999, l_infinity_removed,
      double(l_infinity_true) / double(std::max(1L, l_infinity_removed)),
      double(l_infinity_true) / double(std::max(1L, wrong)));
  EXPECT_GE(precision, 0.9);
  EXPECT_GE(recall, 0.8);
  // The mean of `trials` χ²₆ values has standard deviation sqrt(12 / trials); a band of 4 of
  // them round 6, and few single trials beyond the 99.9% point.
  EXPECT_NEAR(mean_nees, 6.0, 4.0 * std::sqrt(12.0 / trials));
  EXPECT_LE(above_999, std::max(2, trials / 50));
}

}  // namespace
}  // namespace hecal::global
