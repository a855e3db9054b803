#include "hecal/uncertainty/consistency.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "hecal/core/random_draws.h"

namespace hecal::uncertainty {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

TEST(ChiSquare, ClosedFormsAndReferenceValues) {
  // dof 2: CDF = 1 − exp(−x/2); dof 1: CDF = erf(√(x/2)), so the kσ quantile is k².
  for (double x : {0.1, 1.0, 3.0, 10.0}) {
    EXPECT_NEAR(ChiSquareCdf(x, 2), 1.0 - std::exp(-x / 2), 1e-14);
  }
  EXPECT_NEAR(ChiSquareQuantile(SigmaProbability(1.0), 1), 1.0, 1e-10);
  EXPECT_NEAR(ChiSquareQuantile(SigmaProbability(2.0), 1), 4.0, 1e-10);
  EXPECT_NEAR(ChiSquareQuantile(0.5, 2), 2.0 * std::log(2.0), 1e-10);
  // scipy.stats.chi2.ppf (SciPy 1.10).
  EXPECT_NEAR(ChiSquareQuantile(0.95, 6), 12.591587243743977, 1e-8);
  EXPECT_NEAR(ChiSquareQuantile(0.6826894921370859, 6), 7.038400923736641, 1e-8);
  EXPECT_NEAR(SigmaProbability(1.0), 0.6826894921370859, 1e-15);
  EXPECT_EQ(ChiSquareCdf(0.0, 3), 0.0);
  EXPECT_THROW(ChiSquareQuantile(1.0, 3), std::invalid_argument);
  EXPECT_THROW(ChiSquareCdf(1.0, 0.0), std::invalid_argument);
}

TEST(Fisher, ClosedFormsAndLimits) {
  // F(2, 2): CDF = x / (1 + x). F(1, 1) is the square of a Cauchy (Student-t with 1 dof)
  // variable: its p quantile is tan(π p / 2)².
  for (double x : {0.1, 1.0, 3.0, 10.0}) EXPECT_NEAR(FisherCdf(x, 2, 2), x / (1.0 + x), 1e-14);
  EXPECT_NEAR(FisherQuantile(0.9, 2, 2), 9.0, 1e-9);
  const double t = std::tan(0.95 * std::numbers::pi / 2.0);
  EXPECT_NEAR(FisherQuantile(0.95, 1, 1), t * t, 1e-8 * t * t);
  // d2 → ∞: d1 F → χ²(d1).
  EXPECT_NEAR(6.0 * FisherQuantile(0.9973, 6, 1e8), ChiSquareQuantile(0.9973, 6), 1e-5);
  EXPECT_EQ(FisherCdf(0.0, 3, 4), 0.0);
  EXPECT_THROW(FisherQuantile(0.0, 3, 4), std::invalid_argument);
  EXPECT_THROW(FisherCdf(1.0, 3, 0.0), std::invalid_argument);
}

TEST(MeanNeesBand, SixDofTwoHundredTrials) {
  // scipy.stats.chi2.ppf(0.025 / 0.975, 1200) / 200.
  const Interval band = MeanNeesBand(6, 200);
  EXPECT_NEAR(band.low, 5.52944940578029, 1e-8);
  EXPECT_NEAR(band.high, 6.48949138168405, 1e-8);
  EXPECT_TRUE(band.Contains(6.0));
  EXPECT_FALSE(band.Contains(7.0));
}

TEST(Nees, IsTheMahalanobisSquareAndNaNForSingular) {
  MatrixXd C(2, 2);
  C << 4.0, 0.0, 0.0, 0.25;
  EXPECT_NEAR(Nees(VectorXd::Ones(2), C), 0.25 + 4.0, 1e-14);
  EXPECT_TRUE(std::isnan(Nees(VectorXd::Ones(2), MatrixXd::Zero(2, 2))));
}

// Errors drawn from the covariance itself: consistent (mean NEES in its band, coverage within
// 4 standard errors of 68.3/95.5%, sd ratios near 1); the same errors scaled by 1.5 (an
// optimistic covariance): NEES above the band, coverage far below.
TEST(AssessConsistency, DetectsAConsistentAndAnOptimisticCovariance) {
  std::mt19937_64 rng(3);
  hecal::NormalDistribution normal;
  const int trials = 2000;
  std::vector<VectorXd> errors, scaled;
  std::vector<MatrixXd> covariances;
  for (int t = 0; t < trials; ++t) {
    MatrixXd A = MatrixXd::Random(6, 6);
    const MatrixXd C = A * A.transpose() + 0.1 * MatrixXd::Identity(6, 6);
    VectorXd z(6);
    for (int j = 0; j < 6; ++j) z(j) = normal(rng);
    errors.push_back(C.llt().matrixL() * z);
    scaled.push_back(1.5 * errors.back());
    covariances.push_back(C);
  }
  const Consistency good = AssessConsistency(errors, covariances);
  EXPECT_EQ(good.trials, trials);
  EXPECT_EQ(good.dof, 6);
  EXPECT_TRUE(good.band.Contains(good.mean_nees)) << good.mean_nees;
  const double se1 = std::sqrt(0.683 * 0.317 / trials), se2 = std::sqrt(0.955 * 0.045 / trials);
  EXPECT_NEAR(good.coverage_1sigma, SigmaProbability(1.0), 4 * se1);
  EXPECT_NEAR(good.coverage_2sigma, SigmaProbability(2.0), 4 * se2);
  for (int j = 0; j < 6; ++j) EXPECT_NEAR(good.sd_ratio(j), 1.0, 0.1) << j;

  const Consistency bad = AssessConsistency(scaled, covariances);
  EXPECT_GT(bad.mean_nees, bad.band.high);
  EXPECT_LT(bad.coverage_1sigma, 0.45);
  for (int j = 0; j < 6; ++j) EXPECT_NEAR(bad.sd_ratio(j), 1.0 / 1.5, 0.07) << j;
}

TEST(StdRatio, PerAxis) {
  const MatrixXd a = (VectorXd(2) << 4.0, 9.0).finished().asDiagonal();
  const MatrixXd b = (VectorXd(2) << 1.0, 4.0).finished().asDiagonal();
  EXPECT_NEAR(StdRatio(a, b)(0), 2.0, 1e-15);
  EXPECT_NEAR(StdRatio(a, b)(1), 1.5, 1e-15);
}

}  // namespace
}  // namespace hecal::uncertainty
