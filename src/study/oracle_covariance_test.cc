// The oracle covariance (oracle_covariance.h) against independent truth: the study's own trial
// (RunStudy's NEES of the same data set), a covariance known to be right (`ml` with the true
// sigmas of Gaussian noise: its C matches the spread of its estimates, docs/uncertainty.md), the
// leave-one-out NEES recomputed from the M − 1 other redraws directly, and the χ²₆ coverages of
// an exactly Gaussian error.
#include "hecal/study/oracle_covariance.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <random>

#include "hecal/core/random_draws.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/uncertainty/consistency.h"

namespace hecal::study {
namespace {

OracleOptions GivenSigmas(int trials, int redraws) {
  OracleOptions options;
  options.setting.setup = handeye::Setup::kEyeToHand;
  options.setting.stations = 15;
  options.setting.translation_sigma = 1e-3;
  options.setting.rotation_sigma = 1.0 * kRadiansPerDegree;
  options.study.covariance.method = estimation::CovarianceMethod::kLinear;
  options.trials = trials;
  options.redraws = redraws;
  return options;
}

TEST(OracleCovariance, SolvesTheStudysOwnTrials) {
  OracleOptions options = GivenSigmas(2, 8);
  options.first_trial = 3;
  const std::vector<OracleTrial> oracle = OracleCovariance(options);
  StudyOptions study = options.study;
  study.settings = {options.setting};
  study.methods = {estimation::Method::kMl};
  study.trials = 5;
  const StudyResult result = RunStudy(study);
  for (const OracleTrial& trial : oracle) {
    ASSERT_TRUE(trial.ok);
    const TrialResult& same = result.trials[static_cast<size_t>(trial.trial)];
    EXPECT_EQ(trial.error, same.error_X);
    EXPECT_EQ(trial.nees_reported, same.nees);
  }
}

TEST(OracleCovariance, MatchesACovarianceKnownToBeRight) {
  // 400 redraws: each variance of C* within about ±7% (√(2/400)), a trace of three ±5%.
  const std::vector<OracleTrial> oracle = OracleCovariance(GivenSigmas(2, 400));
  for (const OracleTrial& trial : oracle) {
    ASSERT_TRUE(trial.ok);
    EXPECT_EQ(trial.redraws, 400);
    EXPECT_NEAR(trial.det_ratio, 1.0, 0.1) << trial.trial;
    EXPECT_NEAR(trial.rotation_trace_ratio, 1.0, 0.15) << trial.trial;
    EXPECT_NEAR(trial.translation_trace_ratio, 1.0, 0.15) << trial.trial;
  }
}

TEST(OracleCovariance, LeaveOneOutIsTheOtherRedrawsCovariance) {
  const std::vector<OracleTrial> reference = OracleGaussianReference(1, 20, 5);
  const OracleTrial& trial = reference.front();
  ASSERT_TRUE(trial.ok);
  // The same draws in the same order: the trial's own error, then the 20 redraws.
  std::mt19937_64 rng(5);
  hecal::NormalDistribution normal;
  std::vector<Vector6d> errors(21);
  for (Vector6d& e : errors)
    for (int i = 0; i < 6; ++i) e[i] = normal(rng);
  for (size_t j = 1; j < errors.size(); ++j) {
    Matrix6d others = Matrix6d::Zero();
    for (size_t k = 1; k < errors.size(); ++k)
      if (k != j) others += errors[k] * errors[k].transpose();
    others /= 19.0;
    const double direct = errors[j].dot(others.llt().solve(errors[j]));
    EXPECT_NEAR(trial.redraw_nees_oracle_loo[j - 1], direct, 1e-9 * direct);
  }
  EXPECT_NEAR(trial.nees_reported, errors[0].squaredNorm(), 1e-12);
}

TEST(OracleCovariance, AGaussianErrorReadsTheChiSquareCoverages) {
  const OracleSummary summary = SummarizeOracle(OracleGaussianReference(200, 100, 7));
  EXPECT_EQ(summary.trials, 200);
  EXPECT_EQ(summary.redraws, 20000);
  // The right covariance: χ²₆ exactly, 20000 draws (±0.33 / ±0.15 points).
  EXPECT_NEAR(summary.pooled_1sigma_reported, 0.6827, 0.012);
  EXPECT_NEAR(summary.pooled_2sigma_reported, 0.9545, 0.006);
  EXPECT_NEAR(summary.pooled_mean_nees_reported, 6.0, 0.1);
  // In sample the mean NEES is 6 by construction.
  double in_sample = 0.0;
  for (const OracleTrial& trial : OracleGaussianReference(3, 50, 8))
    for (double nees : trial.redraw_nees_oracle) in_sample += nees / 150.0;
  EXPECT_NEAR(in_sample, 6.0, 1e-9);
  // Leave-one-out overstates the NEES by (M − 1)/(M − 8) on average, ≈ 1.076 at M = 100.
  double loo = 0.0;
  for (const OracleTrial& trial : OracleGaussianReference(200, 100, 7))
    for (double nees : trial.redraw_nees_oracle_loo) loo += nees / 20000.0;
  EXPECT_NEAR(loo / 6.0, 99.0 / 92.0, 0.03);
}

}  // namespace
}  // namespace hecal::study
