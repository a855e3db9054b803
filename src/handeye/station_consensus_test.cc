#include "hecal/handeye/station_consensus.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "hecal/core/error.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/so3.h"
#include "testing/handeye_cases.h"
#include "testing/options_validity.h"
#include "testing/scene.h"

namespace hecal::handeye {
namespace {

// Noise-free data: the consensus is every station, the solution exact, the medians zero.
TEST(StationConsensus, NoiseFreeDataAreOneConsensusAndExact) {
  for (handeye::Setup setup : {Setup::kEyeInHand, Setup::kEyeToHand}) {
    for (int n : {3, 5, 12, 40}) {
      const testing::Scene data = testing::ThesisCase(setup, n, 300 + n);
      const StationConsensus consensus = FindStationConsensus(data.MeasuredProblem(), {});
      EXPECT_EQ(std::count(consensus.inlier.begin(), consensus.inlier.end(), true), n);
      EXPECT_LT(testing::Error(consensus.solution.X, data.X).rotation, 1e-9);
      EXPECT_LT(testing::Error(consensus.solution.X, data.X).translation, 1e-9);
      EXPECT_LT(testing::Error(consensus.solution.Z, data.Z).rotation, 1e-9);
      EXPECT_LT(consensus.median_rotation, 1e-9);
      EXPECT_LT(consensus.median_translation, 1e-9);
      EXPECT_GT(consensus.hypotheses, 0);
    }
  }
}

// Random robot poses for up to ⌊(n − 3)/2⌋ = 8 of 20 stations, 1 mm / 1° noise: the consensus
// set excludes every one of them and keeps nearly all good stations; the residual medians are at
// the noise level, not the outliers'.
TEST(StationConsensus, ExcludesGrossOutliersUpToTheRejectionLimit) {
  int good = 0, good_kept = 0;
  for (handeye::Setup setup : {Setup::kEyeInHand, Setup::kEyeToHand}) {
    for (int k : {1, 3, 8}) {
      for (int trial = 0; trial < 10; ++trial) {
        testing::Scene data =
            testing::ThesisCase(setup, 20, 1000 * k + trial, kRadiansPerDegree, 1e-3);
        std::mt19937_64 rng(77 + trial);
        const std::vector<int> replaced = testing::ReplaceRobotPoses(&data, k, rng);
        const StationConsensus consensus = FindStationConsensus(data.MeasuredProblem(), {});
        for (int i = 0; i < 20; ++i) {
          const bool is_outlier = std::count(replaced.begin(), replaced.end(), i) > 0;
          if (is_outlier) {
            EXPECT_FALSE(consensus.inlier[i]) << "k " << k << " trial " << trial << " i " << i;
          } else {
            ++good;
            good_kept += consensus.inlier[i] ? 1 : 0;
          }
        }
        EXPECT_LT(consensus.median_rotation,
                  5.0 * kRadiansPerDegree);            // 2–3.5° for 1° on both devices
        EXPECT_LT(consensus.median_translation, 0.1);  // outliers: tens of degrees, ~1 m
      }
    }
  }
  EXPECT_GE(good_kept, 0.97 * good);
}

// Many stations: random triples (seeded, deterministic) and a scored subset.
TEST(StationConsensus, RandomTriplesAreDeterministicAndStillFindTheConsensus) {
  testing::Scene data =
      testing::ThesisCase(Setup::kEyeInHand, 60, 9, 0.5 * kRadiansPerDegree, 5e-4);
  std::mt19937_64 rng(3);
  const std::vector<int> replaced = testing::ReplaceRobotPoses(&data, 12, rng);
  ConsensusOptions options;
  options.max_hypotheses = 100;  // below RequiredHypotheses(60): the cap binds
  options.max_scored_stations = 30;
  const StationConsensus a = FindStationConsensus(data.MeasuredProblem(), options);
  const StationConsensus b = FindStationConsensus(data.MeasuredProblem(), options);
  EXPECT_EQ(a.inlier, b.inlier);
  EXPECT_TRUE(a.solution.X.isApprox(b.solution.X, 0.0));
  EXPECT_EQ(a.hypotheses, 100);
  for (int i : replaced) EXPECT_FALSE(a.inlier[i]) << i;
}

// The number of random triples: the smallest N with P(Binomial(N, p) < 5) ≤ 1e-9, p the
// probability that a triple avoids ⌊(n − 3)/2⌋ outliers, C(n − m, 3) / C(n, 3) — values computed
// independently (exact binomial sums in Python). Small sets solve every triple instead.
TEST(StationConsensus, HypothesisCountFollowsTheBreakdownBound) {
  EXPECT_EQ(RequiredHypotheses(2), 0);
  EXPECT_EQ(RequiredHypotheses(4), 5);  // m = 0: every triple is clean
  EXPECT_EQ(RequiredHypotheses(10), 94);
  EXPECT_EQ(RequiredHypotheses(20), 149);
  EXPECT_EQ(RequiredHypotheses(50), 197);
  EXPECT_EQ(RequiredHypotheses(1000), 236);
  EXPECT_EQ(RequiredHypotheses(10000), 238);
  // 9 stations: 84 triples, fewer than the bound, so all of them.
  const testing::Scene nine =
      testing::ThesisCase(Setup::kEyeInHand, 9, 21, kRadiansPerDegree, 1e-3);
  EXPECT_EQ(FindStationConsensus(nine.MeasuredProblem(), {}).hypotheses, 84);
  const testing::Scene fifty =
      testing::ThesisCase(Setup::kEyeInHand, 50, 22, kRadiansPerDegree, 1e-3);
  EXPECT_EQ(FindStationConsensus(fifty.MeasuredProblem(), {}).hypotheses, 197);
}

// Sizes of a residual: rotation angle accurate at tiny angles and near π.
TEST(StationConsensus, ResidualSizeIsAccurateNearZeroAndPi) {
  const testing::Scene data = testing::ThesisCase(Setup::kEyeInHand, 3, 5);
  const Problem problem = data.MeasuredProblem();
  for (double angle : {1e-12, 1e-6, 0.5, std::numbers::pi - 1e-9}) {
    Solution solution{data.X, data.Z};
    solution.Z.linear() = solution.Z.linear() * so3::Exp(Eigen::Vector3d(0.0, 0.0, angle));
    const StationError error = StationResidualSize(problem, 1, solution);
    EXPECT_NEAR(error.rotation, angle, 1e-12 + 1e-12 * angle);
  }
}

// Degenerate data (one rotation axis) and fewer than 3 stations are refused as degenerate.
TEST(StationConsensus, DegenerateDataAreRefused) {
  Problem problem;
  std::mt19937_64 rng(4);
  for (int i = 0; i < 6; ++i) {
    problem.A.push_back(
        MakePose(so3::Exp(Eigen::Vector3d(0.0, 0.0, 0.3 * i)), Eigen::Vector3d(0.1 * i, 0.0, 0.5)));
    problem.B.push_back(testing::RandomPose(rng));
  }
  EXPECT_THROW(FindStationConsensus(problem, {}), DegenerateError);
  problem.A.resize(2);
  problem.B.resize(2);
  EXPECT_THROW(FindStationConsensus(problem, {}), DegenerateError);
}

TEST(SubProblem, KeepsTheFlaggedStationsInOrder) {
  const testing::Scene data = testing::ThesisCase(Setup::kEyeToHand, 5, 6);
  const Problem problem = data.MeasuredProblem();
  const Problem sub = SubProblem(problem, {true, false, true, false, true});
  ASSERT_EQ(sub.A.size(), 3u);
  EXPECT_EQ(sub.setup, Setup::kEyeToHand);
  EXPECT_TRUE(sub.A[1].isApprox(problem.A[2], 0.0));
  EXPECT_TRUE(sub.B[2].isApprox(problem.B[4], 0.0));
}

TEST(ConsensusOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const ConsensusOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "ConsensusOptions.max_hypotheses",
                            [](auto& o) { o.max_hypotheses = 0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "ConsensusOptions.max_scored_stations",
                            [](auto& o) { o.max_scored_stations = 2; }));
}

}  // namespace
}  // namespace hecal::handeye
