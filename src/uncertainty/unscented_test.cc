#include "hecal/uncertainty/unscented.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "hecal/core/error.h"
#include "hecal/core/random_draws.h"
#include "hecal/geometry/se3.h"
#include "hecal/uncertainty/monte_carlo.h"
#include "testing/random_poses.h"

namespace hecal::uncertainty {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

MatrixXd RandomCovariance(int n, std::mt19937_64& rng) {
  hecal::NormalDistribution normal;
  MatrixXd A(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) A(i, j) = normal(rng);
  }
  return A * A.transpose() + 0.1 * MatrixXd::Identity(n, n);
}

std::vector<UnscentedParameters> EveryForm() {
  return {UnscentedParameters::Symmetric(),           UnscentedParameters::Symmetric(0.0),
          UnscentedParameters::Symmetric(0.5),        UnscentedParameters::Symmetric(-3.0),
          UnscentedParameters::Scaled(1.0, 2.0, 0.0), UnscentedParameters::Scaled(1e-3, 2.0, 0.0),
          UnscentedParameters::Scaled(0.5, 0.0, 3.0), UnscentedParameters::Scaled(1.0, 2.0, -1.0)};
}

// 1e-12, except for a scaled set with tiny α: its weights are ~1/α², and the rounding of the
// f(x_i) (~1e-16 |y| each) is amplified by Σ|w_i| (2e6 for α = 1e-3, n = 5).
double Tolerance(int n, const UnscentedParameters& p) {
  const SigmaWeights w = Weights(n, p);
  return std::max(1e-12, 1e-14 * (std::abs(w.mean_centre) + 2.0 * n * w.other));
}

TEST(SquareRoot, ReproducesTheCovarianceBothWays) {
  std::mt19937_64 rng(1);
  const MatrixXd C = RandomCovariance(7, rng);
  for (SquareRoot kind : {SquareRoot::kCholesky, SquareRoot::kSymmetric}) {
    const MatrixXd S = CovarianceSquareRoot(C, kind);
    EXPECT_LT((S * S.transpose() - C).norm(), 1e-12 * C.norm());
  }
  // Cholesky: lower triangular; symmetric root: symmetric.
  const MatrixXd L = CovarianceSquareRoot(C, SquareRoot::kCholesky);
  EXPECT_EQ(L.triangularView<Eigen::StrictlyUpper>().toDenseMatrix().norm(), 0.0);
  const MatrixXd R = CovarianceSquareRoot(C, SquareRoot::kSymmetric);
  EXPECT_LT((R - R.transpose()).norm(), 1e-12);
}

TEST(SquareRoot, SemidefiniteFallsBackToTheSymmetricRoot) {
  MatrixXd C = MatrixXd::Zero(4, 4);
  C(0, 0) = 4.0;
  C(2, 2) = 1.0;  // rows 1 and 3: no noise
  const MatrixXd S = CovarianceSquareRoot(C, SquareRoot::kCholesky);
  EXPECT_LT((S * S.transpose() - C).norm(), 1e-14);
  EXPECT_EQ(S.col(1).norm(), 0.0);
  EXPECT_EQ(S.col(3).norm(), 0.0);
}

TEST(SquareRoot, RejectsIndefiniteAsymmetricAndNonFinite) {
  MatrixXd C = MatrixXd::Identity(3, 3);
  C(1, 1) = -1.0;
  EXPECT_THROW(CovarianceSquareRoot(C, SquareRoot::kCholesky), std::invalid_argument);
  C = MatrixXd::Identity(3, 3);
  C(0, 1) = 0.5;
  EXPECT_THROW(CovarianceSquareRoot(C, SquareRoot::kSymmetric), std::invalid_argument);
  C = MatrixXd::Identity(3, 3);
  C(2, 2) = std::nan("");
  EXPECT_THROW(CovarianceSquareRoot(C, SquareRoot::kCholesky), std::invalid_argument);
}

TEST(Weights, MeanWeightsSumToOneAndPointsReproduceTheCovariance) {
  for (int n : {1, 2, 3, 6, 13, 180}) {
    for (const UnscentedParameters& p : EveryForm()) {
      if (!p.IsValid(n, nullptr)) continue;  // kappa = −1 with n = 1
      const SigmaWeights w = Weights(n, p);
      EXPECT_NEAR(w.mean_centre + 2 * n * w.other, 1.0, 1e-12) << n;
      // Σ w_i (x_i − x̄)(x_i − x̄)ᵀ = 2 n·w·c² S_i S_iᵀ/n per column: w·2·c² = 1.
      EXPECT_NEAR(2.0 * w.other * w.spread * w.spread, 1.0, 1e-12) << n;
    }
  }
}

TEST(Weights, SymmetricDefaultPutsThePointsAtSqrtThreeSigma) {
  for (int n : {1, 6, 180}) {
    const SigmaWeights w = Weights(n, UnscentedParameters::Symmetric());
    EXPECT_NEAR(w.spread, std::sqrt(3.0), 1e-12);
    EXPECT_NEAR(w.mean_centre, 1.0 - n / 3.0, 1e-12);
  }
}

TEST(Weights, InvalidParametersAreRejected) {
  std::string why;
  EXPECT_FALSE(UnscentedParameters::Symmetric(1.0).IsValid(3, &why));
  EXPECT_NE(why.find("w0"), std::string::npos);
  EXPECT_FALSE(UnscentedParameters::Scaled(0.0, 2.0, 0.0).IsValid(3, &why));
  EXPECT_FALSE(UnscentedParameters::Scaled(1.0, 2.0, -3.0).IsValid(3, &why));
  EXPECT_FALSE(UnscentedParameters::Symmetric().IsValid(0, &why));
  EXPECT_THROW(Weights(3, UnscentedParameters::Symmetric(2.0)), InputError);
}

TEST(UnscentedTransform, ExactForLinearMaps) {
  std::mt19937_64 rng(2);
  const int n = 5, m = 3;
  hecal::NormalDistribution normal;
  MatrixXd A(m, n);
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < n; ++j) A(i, j) = normal(rng);
  }
  const VectorXd b = VectorXd::Random(m);
  const VectorXd mean = VectorXd::Random(n);
  const MatrixXd C = RandomCovariance(n, rng);
  auto f = [&](const VectorXd& x) -> VectorXd { return A * x + b; };
  for (const UnscentedParameters& p : EveryForm()) {
    for (SquareRoot root : {SquareRoot::kCholesky, SquareRoot::kSymmetric}) {
      UnscentedParameters q = p;
      q.square_root = root;
      const Moments<VectorXd> y = UnscentedTransform<VectorXd, VectorXd>(f, mean, C, q);
      EXPECT_LT((y.mean - (A * mean + b)).cwiseAbs().maxCoeff(), Tolerance(n, q));
      const MatrixXd expected = A * C * A.transpose();
      // The scaled form's covariance centre weight is (f(x̄) − ȳ)-weighted: zero for linear f.
      EXPECT_LT((y.covariance - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.norm());
      EXPECT_EQ(y.evaluations, 2 * n + 1);
    }
  }
}

// Analytic moments of a quadratic map, x ~ N(μ, diag(s1², s2²)), v_k = s_k²:
//   y1 = x1² + 3 x2:  E = μ1² + v1 + 3 μ2,  Var = 4 μ1² v1 + 2 v1² + 9 v2
//   y2 = 2 x2 − x1:   E = 2 μ2 − μ1,        Var = 4 v2 + v1,   Cov(y1, y2) = 6 v2 − 2 μ1 v1
// (Gaussian moments E[z³] = 0, E[z⁴] = 3 s⁴). The mean is exact for every quadratic and every
// parameter choice; the default w0 = 1 − n/3 matches E[z⁴] per axis, so the covariance is exact
// too (a product of two squared axes, x1² x2², would need E[z1² z2²], which no symmetric set
// carries — the UT's known limit, not tested as exact).
TEST(UnscentedTransform, MatchesAnalyticMomentsOfAQuadraticMap) {
  const double m1 = 0.7, m2 = -1.3, s1 = 0.4, s2 = 0.9;
  VectorXd mean(2);
  mean << m1, m2;
  MatrixXd C = MatrixXd::Zero(2, 2);
  C(0, 0) = s1 * s1;
  C(1, 1) = s2 * s2;
  auto f = [](const VectorXd& x) -> VectorXd {
    VectorXd y(2);
    y << x(0) * x(0) + 3.0 * x(1), 2.0 * x(1) - x(0);
    return y;
  };
  const double v1 = s1 * s1, v2 = s2 * s2;
  VectorXd expected_mean(2);
  expected_mean << m1 * m1 + v1 + 3.0 * m2, 2.0 * m2 - m1;
  MatrixXd expected_cov(2, 2);
  expected_cov << 4 * m1 * m1 * v1 + 2 * v1 * v1 + 9 * v2, 6 * v2 - 2 * m1 * v1,
      6 * v2 - 2 * m1 * v1, 4 * v2 + v1;
  const Moments<VectorXd> y = UnscentedTransform<VectorXd, VectorXd>(f, mean, C);
  EXPECT_LT((y.mean - expected_mean).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((y.covariance - expected_cov).cwiseAbs().maxCoeff(), 1e-12);
  for (const UnscentedParameters& p : EveryForm()) {
    EXPECT_LT((UnscentedTransform<VectorXd, VectorXd>(f, mean, C, p).mean - expected_mean)
                  .cwiseAbs()
                  .maxCoeff(),
              Tolerance(2, p));
  }
  // Scaled with α = 1, β = 0, κ = 3 − n = 1: the same points and weights as the default.
  const Moments<VectorXd> scaled =
      UnscentedTransform<VectorXd, VectorXd>(f, mean, C, UnscentedParameters::Scaled(1, 0, 1));
  EXPECT_LT((scaled.covariance - expected_cov).cwiseAbs().maxCoeff(), 1e-12);
}

// y = |x|², x ~ N(0, I₆), default set (w0 = −1, points at ±√3): the standard form would give
// w0 (0 − 6)² + 12 · (1/6) (3 − 6)² = −18, a negative variance; the modified form about y_0
// gives 12 · (1/6) · 3² = 18 ≥ 0 (the true variance is 12: cross terms are beyond the set).
TEST(UnscentedTransform, NegativeCentreWeightUsesTheModifiedFormAndStaysSemidefinite) {
  auto f = [](const VectorXd& x) -> VectorXd { return VectorXd::Constant(1, x.squaredNorm()); };
  const Moments<VectorXd> y =
      UnscentedTransform<VectorXd, VectorXd>(f, VectorXd::Zero(6), MatrixXd::Identity(6, 6));
  EXPECT_NEAR(y.mean(0), 6.0, 1e-12);  // the mean is exact
  EXPECT_NEAR(y.covariance(0, 0), 18.0, 1e-12);
}

TEST(UnscentedTransform, ZeroColumnsAreNotEvaluated) {
  MatrixXd C = MatrixXd::Zero(4, 4);
  C(1, 1) = 1.0;
  int calls = 0;
  auto f = [&](const VectorXd& x) -> VectorXd {
    ++calls;
    return x;
  };
  const Moments<VectorXd> y = UnscentedTransform<VectorXd, VectorXd>(f, VectorXd::Zero(4), C);
  EXPECT_EQ(calls, 3);
  EXPECT_EQ(y.evaluations, 3);
  EXPECT_LT((y.covariance - C).norm(), 1e-12);
}

TEST(UnscentedTransform, ThreadsGiveTheSameResult) {
  std::mt19937_64 rng(3);
  const MatrixXd C = RandomCovariance(6, rng);
  auto f = [](const VectorXd& x) -> VectorXd { return x.array().sin(); };
  const VectorXd mean = VectorXd::Constant(6, 0.3);
  const auto one = UnscentedTransform<VectorXd, VectorXd>(f, mean, C, {}, 1);
  const auto four = UnscentedTransform<VectorXd, VectorXd>(f, mean, C, {}, 4);
  EXPECT_EQ((one.covariance - four.covariance).norm(), 0.0);
  EXPECT_EQ((one.mean - four.mean).norm(), 0.0);
}

// On SE(3): T = A · B with independent right perturbations of A and B (12-D input, poses with
// rotations near 0 and near π), against a 20000-sample Monte Carlo of the same map. First
// order: Cov(T) = Ad(B⁻¹) Σ_A Ad(B⁻¹)ᵀ + Σ_B; the UT must agree with MC within its sampling
// error (3 standard errors per axis plus 1%), and both sit near the first-order value.
TEST(UnscentedTransform, PoseCompositionOnTheManifoldMatchesMonteCarlo) {
  std::mt19937_64 rng(4);
  const std::vector<std::pair<Pose, Pose>> cases = {
      {testing::RandomPose(rng), testing::RandomPose(rng)},
      {MakePose(so3::Exp(Eigen::Vector3d(0, 0, std::numbers::pi - 1e-3)),
                Eigen::Vector3d(0.2, -0.1, 0.5)),
       MakePose(so3::Exp(Eigen::Vector3d(std::numbers::pi - 0.02, 0, 0)),
                Eigen::Vector3d(0.4, 0.3, -0.2))},
      {Pose::Identity(), testing::RandomPose(rng)}};
  MatrixXd C = MatrixXd::Zero(12, 12);
  C.topLeftCorner<3, 3>() = 0.05 * 0.05 * Eigen::Matrix3d::Identity();  // rad²
  C.block<3, 3>(3, 3) = 0.02 * 0.02 * Eigen::Matrix3d::Identity();      // m²
  C.block<3, 3>(6, 6) = 0.08 * 0.08 * Eigen::Matrix3d::Identity();
  C.block<3, 3>(9, 9) = 0.01 * 0.01 * Eigen::Matrix3d::Identity();
  C(0, 1) = C(1, 0) = 0.5 * 0.05 * 0.05;  // correlated rotation axes of A
  auto compose = [](const std::vector<Pose>& ab) -> Pose { return ab[0] * ab[1]; };
  MonteCarloOptions mc_options;
  mc_options.samples = 20000;
  mc_options.seed = 7;
  for (const auto& [A, B] : cases) {
    const std::vector<Pose> input = {A, B};
    const Moments<Pose> ut = UnscentedTransform<std::vector<Pose>, Pose>(compose, input, C);
    const MonteCarloMoments<Pose> mc =
        MonteCarloTransform<std::vector<Pose>, Pose>(compose, input, C, mc_options);
    const Eigen::VectorXd ut_sd = ut.covariance.diagonal().cwiseSqrt();
    const Eigen::VectorXd mc_sd = mc.covariance.diagonal().cwiseSqrt();
    for (int j = 0; j < 6; ++j) {
      EXPECT_NEAR(ut_sd(j), mc_sd(j), 3.0 * mc.sd_std_error(j) + 0.01 * mc_sd(j)) << j;
    }
    // Means: the UT mean within 3 standard errors of the MC mean, per axis.
    const VectorXd d = Manifold<Pose>::Minus(ut.mean, mc.mean);
    for (int j = 0; j < 6; ++j) EXPECT_LT(std::abs(d(j)), 3.0 * mc.mean_std_error(j)) << j;
    // First order, for scale: within 5% per axis at these noise levels.
    const Matrix6d Ad = se3::Adjoint(B.inverse());
    const Matrix6d linear =
        Ad * C.topLeftCorner<6, 6>() * Ad.transpose() + C.bottomRightCorner<6, 6>();
    for (int j = 0; j < 6; ++j) {
      EXPECT_NEAR(ut_sd(j), std::sqrt(linear(j, j)), 0.05 * std::sqrt(linear(j, j))) << j;
    }
  }
}

TEST(UnscentedTransform, RotationMeanOnSo3IsIterative) {
  // Rotations about z near π: the vector-space average of matrices would not be a rotation;
  // the manifold mean is exactly R·Exp(0) by symmetry of the points.
  const Eigen::Matrix3d R = so3::Exp(Eigen::Vector3d(0, 0, std::numbers::pi - 1e-4));
  const MatrixXd C = 0.3 * 0.3 * MatrixXd::Identity(3, 3);
  auto identity = [](const Eigen::Matrix3d& S) -> Eigen::Matrix3d { return S; };
  const Moments<Eigen::Matrix3d> y =
      UnscentedTransform<Eigen::Matrix3d, Eigen::Matrix3d>(identity, R, C);
  EXPECT_LT(so3::Distance(y.mean, R), 1e-10);
  EXPECT_LT((y.mean.transpose() * y.mean - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  EXPECT_LT((y.covariance - C).norm(), 1e-10);
}

}  // namespace
}  // namespace hecal::uncertainty
