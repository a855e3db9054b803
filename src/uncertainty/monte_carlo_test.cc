#include "hecal/uncertainty/monte_carlo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "hecal/core/error.h"
#include "hecal/core/limits.h"
#include "testing/options_validity.h"

namespace hecal::uncertainty {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

MatrixXd TestCovariance() {
  MatrixXd C(3, 3);
  C << 4.0, 1.0, 0.0, 1.0, 2.0, -0.5, 0.0, -0.5, 1.0;
  return C;
}

// A linear map: the MC mean and covariance must be within their own reported sampling errors of
// the exact values (4 standard errors: the test fails by chance with probability ~1e-4 per axis
// for a correct implementation, and the seed is fixed).
TEST(MonteCarloTransform, LinearMapWithinItsOwnSamplingError) {
  MatrixXd A(2, 3);
  A << 1.0, 2.0, 0.0, -1.0, 0.5, 3.0;
  const VectorXd mean = (VectorXd(3) << 1.0, -2.0, 0.5).finished();
  auto f = [&](const VectorXd& x) -> VectorXd { return A * x; };
  MonteCarloOptions options;
  options.samples = 20000;
  options.seed = 11;
  const MonteCarloMoments<VectorXd> y =
      MonteCarloTransform<VectorXd, VectorXd>(f, mean, TestCovariance(), options);
  const MatrixXd expected = A * TestCovariance() * A.transpose();
  EXPECT_EQ(y.samples, 20000);
  EXPECT_EQ(y.failures, 0);
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(y.mean(j), (A * mean)(j), 4.0 * y.mean_std_error(j)) << j;
    EXPECT_NEAR(std::sqrt(y.covariance(j, j)), std::sqrt(expected(j, j)), 4.0 * y.sd_std_error(j))
        << j;
    // The reported errors are the textbook ones for Gaussian output: σ/√N and σ/√(2N).
    EXPECT_NEAR(y.mean_std_error(j), std::sqrt(expected(j, j) / 20000.0),
                0.05 * y.mean_std_error(j));
    EXPECT_NEAR(y.sd_std_error(j), std::sqrt(expected(j, j) / 40000.0), 0.1 * y.sd_std_error(j));
  }
}

TEST(MonteCarloTransform, SameSeedSameResultWhateverTheThreads) {
  auto f = [](const VectorXd& x) -> VectorXd { return x.array().exp(); };
  MonteCarloOptions options;
  options.samples = 500;
  options.threads = 1;
  const auto one = MonteCarloTransform<VectorXd, VectorXd>(f, VectorXd::Zero(3),
                                                           TestCovariance() * 0.01, options);
  options.threads = 3;
  const auto three = MonteCarloTransform<VectorXd, VectorXd>(f, VectorXd::Zero(3),
                                                             TestCovariance() * 0.01, options);
  EXPECT_EQ((one.covariance - three.covariance).norm(), 0.0);
  options.seed = 2;
  const auto other = MonteCarloTransform<VectorXd, VectorXd>(f, VectorXd::Zero(3),
                                                             TestCovariance() * 0.01, options);
  EXPECT_GT((one.covariance - other.covariance).norm(), 0.0);
}

TEST(MonteCarloTransform, FailedSamplesAreCountedNotHidden) {
  // f fails for x0 > 1 (throws) and is non-finite for x1 > 1.5.
  auto f = [](const VectorXd& x) -> VectorXd {
    if (x(0) > 1.0) throw std::runtime_error("beyond the domain");
    VectorXd y = x;
    if (x(1) > 1.5) y(1) = std::nan("");
    return y;
  };
  MonteCarloOptions options;
  options.samples = 4000;
  const auto y = MonteCarloTransform<VectorXd, VectorXd>(f, VectorXd::Zero(2),
                                                         MatrixXd::Identity(2, 2), options);
  // P(x0 > 1) = 0.159, P(x0 ≤ 1 and x1 > 1.5) = 0.841 × 0.0668.
  const double expected_failures = 4000 * (0.1587 + 0.8413 * 0.0668);
  EXPECT_NEAR(y.failures, expected_failures, 4.0 * std::sqrt(expected_failures));
  EXPECT_EQ(y.samples + y.failures, 4000);
  EXPECT_FALSE(y.first_failure.empty());
}

TEST(MonteCarloTransform, RejectsBadArguments) {
  auto f = [](const VectorXd& x) -> VectorXd { return x; };
  MonteCarloOptions options;
  options.samples = 1;
  EXPECT_THROW((MonteCarloTransform<VectorXd, VectorXd>(f, VectorXd::Zero(2),
                                                        MatrixXd::Identity(2, 2), options)),
               InputError);
  options.samples = 10;
  EXPECT_THROW((MonteCarloTransform<VectorXd, VectorXd>(f, VectorXd::Zero(2),
                                                        MatrixXd::Identity(3, 3), options)),
               std::invalid_argument);
  auto always_fails = [](const VectorXd& x) -> VectorXd {
    if (x.norm() > 0.0) throw std::runtime_error("no");
    return x;
  };
  EXPECT_THROW((MonteCarloTransform<VectorXd, VectorXd>(always_fails, VectorXd::Zero(2),
                                                        MatrixXd::Identity(2, 2), options)),
               DegenerateError);
}

TEST(StandardNormalSample, IsDeterministicPerSeedAndIndex) {
  EXPECT_EQ((StandardNormalSample(5, 17, 4) - StandardNormalSample(5, 17, 4)).norm(), 0.0);
  EXPECT_GT((StandardNormalSample(5, 17, 4) - StandardNormalSample(5, 18, 4)).norm(), 0.0);
  EXPECT_GT((StandardNormalSample(5, 17, 4) - StandardNormalSample(6, 17, 4)).norm(), 0.0);
}

TEST(MonteCarloOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const MonteCarloOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "MonteCarloOptions.samples", [](auto& o) { o.samples = 1; }));
  EXPECT_TRUE(
      RefusesNaming(defaults, "MonteCarloOptions.threads", [](auto& o) { o.threads = -1; }));
  EXPECT_TRUE(RefusesNaming(defaults, "MonteCarloOptions.threads",
                            [](auto& o) { o.threads = kMaxThreads + 1; }));
}

}  // namespace
}  // namespace hecal::uncertainty
