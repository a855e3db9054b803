// Wrong matches among 0.5 px noisy pairs are removed (precision and recall against the scene's
// truth), and X lands within the L2 polish's covariance of the truth.
#include "hecal/global/outlier_removal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <set>
#include <string>

#include "hecal/core/random_draws.h"
#include "hecal/estimation/epipolar_polish.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"
#include "testing/epipolar_scenes.h"

namespace hecal::global {
namespace {

// 3 motions of 40 ray pairs, 0.5 px noise, 10% wrong matches.
testing::EpipolarSceneSpec NoisySpec() {
  testing::EpipolarSceneSpec spec;
  spec.motions = 3;
  spec.pairs = 40;
  spec.pixel_sigma = 0.5;
  spec.wrong_fraction = 0.1;
  return spec;
}

// The time budget is for all the solves together: on a clock that moves one second per reading
// the rounds and the last solve stop within it, and the result is a valid, uncertified X.
TEST(SolveGlobalRobust, StopsWhenTheTimeBudgetRunsOut) {
  const testing::EpipolarSceneSpec spec = NoisySpec();
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 31);
  SearchOptions search;
  search.epsilon = 1e-7;  // far below the noise: no solve can close it in a few batches
  search.translation_bound = 1.0;
  search.time_budget = 8.0;
  auto now = std::make_shared<double>(0.0);
  search.clock = [now] { return *now += 1.0; };
  int reports = 0;
  search.progress = [&reports](const SearchProgress& p) {
    ++reports;
    EXPECT_LE(p.lower, p.upper);
    EXPECT_GE(p.round, 1);
  };
  search.progress_interval = 1.0;
  OutlierOptions options;
  options.threshold = 4.0 * 0.5 / spec.focal * std::sqrt(2.0);
  const RobustGlobalSolution robust = SolveGlobalRobust(scene.problem, search, options);
  const Certificate& c = robust.solution.certificate;
  EXPECT_FALSE(c.certified);
  EXPECT_EQ(c.stopped_by, StopReason::kTimeBudget);
  EXPECT_GE(c.lower, 0.0);
  EXPECT_LE(c.lower, c.upper);
  EXPECT_NEAR(c.upper, MaxRayError(robust.inliers, robust.solution.X), 1e-12);
  EXPECT_GE(robust.rounds, 1);
  EXPECT_GT(reports, 0);
  // Every solve checks its budget before a batch: the whole run overshoots by a few readings.
  EXPECT_GE(robust.seconds, search.time_budget);
  EXPECT_LE(robust.seconds, search.time_budget + 4.0 * robust.rounds);
}

TEST(SolveGlobalRobust, RemovesWrongMatchesWithHighPrecisionAndRecall) {
  const testing::EpipolarSceneSpec spec = NoisySpec();
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

TEST(SolveGlobalRobust, KeepsCorrectMatchesWhenTheRobotNoiseExceedsThePixelThreshold) {
  // Clean 0.1 px rays, but each hand motion off by ~5e-3 rad and ~3 mm: the epipolar errors are
  // set by the robot, several times the threshold derived from the pixels. The pre-filter (no
  // robot data) keeps every pair, and the L∞ rounds, whose threshold follows the data's own
  // error level at the local start, remove none (there is no wrong match to remove).
  testing::EpipolarSceneSpec spec;
  spec.motions = 4;
  spec.pairs = 30;
  spec.pixel_sigma = 0.1;
  testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 8);
  std::mt19937_64 rng(17);
  hecal::NormalDistribution normal(0.0, 1.0);
  for (EpipolarMotion& motion : scene.problem.motions) {
    // Drawn last to first: the order these tests' data were generated in.
    const double omega_z = normal(rng), omega_y = normal(rng), omega_x = normal(rng);
    const Eigen::Vector3d omega(omega_x, omega_y, omega_z);
    const double shift_z = normal(rng), shift_y = normal(rng), shift_x = normal(rng);
    const Eigen::Vector3d shift(shift_x, shift_y, shift_z);
    motion.hand = motion.hand * MakePose(so3::Exp(3e-3 * omega), 2e-3 * shift);
  }
  SearchOptions search;
  search.epsilon = 1e-4;
  search.relative_gap = 0.5;
  search.max_cubes = 5'000;  // the removal's decisions, not the last solve's certificate
  search.translation_bound = 1.0;
  OutlierOptions options;
  options.threshold = 4.0 * std::sqrt(2.0) * spec.pixel_sigma / spec.focal;
  const RobustGlobalSolution robust = SolveGlobalRobust(scene.problem, search, options);
  EXPECT_GT(MaxRayError(scene.problem, scene.X), options.threshold);  // the premise
  EXPECT_GT(robust.threshold, options.threshold);
  EXPECT_TRUE(robust.removed.empty()) << robust.removed.size() << " removed";
}

TEST(PrefilterPairs, KeepsEveryPairOfANoiseFreeScene) {
  testing::EpipolarSceneSpec spec;
  const testing::EpipolarScene scene = testing::MakeEpipolarScene(spec, 4);
  std::vector<RemovedPair> removed;
  const EpipolarProblem kept = PrefilterPairs(scene.problem, OutlierOptions{}, &removed);
  EXPECT_TRUE(removed.empty());
  EXPECT_EQ(PairCount(kept), PairCount(scene.problem));
}

TEST(OutlierOptions, IsValidNamesTheBadField) {
  EXPECT_TRUE(OutlierOptions{}.IsValid(nullptr));
  const auto bad = [](auto change) {
    OutlierOptions options;
    change(options);
    std::string why;
    EXPECT_FALSE(options.IsValid(&why));
    return why;
  };
  EXPECT_NE(bad([](OutlierOptions& o) { o.threshold = 0.0; }).find("threshold"), std::string::npos);
  EXPECT_NE(bad([](OutlierOptions& o) { o.threshold = INFINITY; }).find("threshold"),
            std::string::npos);
  EXPECT_NE(bad([](OutlierOptions& o) { o.error_level_multiple = -1.0; }).find("error_level"),
            std::string::npos);
  EXPECT_NE(bad([](OutlierOptions& o) { o.ransac_iterations = 0; }).find("ransac_iterations"),
            std::string::npos);
  EXPECT_NE(bad([](OutlierOptions& o) { o.max_rounds = 0; }).find("max_rounds"), std::string::npos);
}

}  // namespace
}  // namespace hecal::global
