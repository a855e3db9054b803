#include "loop_solver.h"

#include <ceres/problem.h>
#include <ceres/solver.h>
#include <gtest/gtest.h>

#include <memory>
#include <numbers>
#include <random>
#include <string>

#include "hecal/core/random_draws.h"
#include "hecal/estimation/robust_loss.h"
#include "hecal/estimation/se3_manifold.h"
#include "hecal/estimation/station_covariance.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"
#include "small_problem.h"
#include "testing/handeye_cases.h"

namespace hecal::estimation::internal {
namespace {

struct Case {
  std::string name;
  handeye::Problem problem;
  handeye::Solution truth;
  std::vector<Matrix6d> whitening;
};

// Camera noise of 0.2° / 0.5 mm per component on every station (one gross outlier at station 3
// when asked), the whitening of a 0.2° / 0.5 mm model on both devices evaluated at the true X.
Case MakeCase(const std::string& name, const testing::Scene& data, uint64_t seed, bool outlier) {
  std::mt19937_64 rng(seed);
  hecal::NormalDistribution normal;
  const PoseSigma sigma{0.2 * kRadiansPerDegree, 0.5e-3};
  Case c{name, data.MeasuredProblem(), {data.X, data.Z}, {}};
  for (Pose& B : c.problem.B) {
    Vector6d e;
    for (int k = 0; k < 6; ++k) e(k) = normal(rng) * (k < 3 ? sigma.rotation : sigma.translation);
    B = B * se3::Exp(e);
  }
  if (outlier) {
    Vector6d gross;
    gross << 0.0, 10.0 * kRadiansPerDegree, 0.0, 0.05, 0.0, 0.0;
    c.problem.B[3] = c.problem.B[3] * se3::Exp(gross);
  }
  for (size_t i = 0; i < c.problem.A.size(); ++i) {
    c.whitening.push_back(WhiteningMatrix(
        StationCovariance(c.problem.setup, c.problem.A[i], c.problem.B[i], data.X, sigma, sigma)));
  }
  return c;
}

// Both setups; X of a random rotation, of 1e-5 rad (near identity), of π − 1e-4 and of exactly π.
std::vector<Case> Cases(bool outlier) {
  std::vector<Case> cases;
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const std::string prefix(handeye::SetupName(setup));
    cases.push_back(MakeCase(prefix + " thesis", testing::ThesisCase(setup, 20, 71), 81, outlier));
    cases.push_back(MakeCase(prefix + " X near identity",
                             testing::WideRotationCase(setup, 12, 72, 1e-5), 82, outlier));
    cases.push_back(MakeCase(prefix + " X near pi",
                             testing::WideRotationCase(setup, 12, 73, std::numbers::pi - 1e-4), 83,
                             outlier));
    cases.push_back(MakeCase(prefix + " X at pi",
                             testing::WideRotationCase(setup, 12, 74, std::numbers::pi), 84,
                             outlier));
  }
  return cases;
}

// The same cost minimised by Ceres (LoopCost on Se3RightManifold, hecal's small-problem
// settings): an independent minimiser.
handeye::Solution CeresMinimum(const Case& c, const ceres::LossFunction* loss,
                               const handeye::Solution& start) {
  double x[kPoseAmbientSize], z[kPoseAmbientSize];
  PoseToParameters(start.X, x);
  PoseToParameters(start.Z, z);
  Se3RightManifold manifold;
  ceres::Problem problem(SmallProblemOptions());
  problem.AddParameterBlock(x, kPoseAmbientSize, &manifold);
  problem.AddParameterBlock(z, kPoseAmbientSize, &manifold);
  for (size_t i = 0; i < c.whitening.size(); ++i) {
    problem.AddResidualBlock(LoopCost::Create(c.problem.A[i], c.problem.B[i], c.whitening[i]),
                             const_cast<ceres::LossFunction*>(loss), x, z);
  }
  ceres::Solver::Summary summary;
  ceres::Solve(SmallSolverOptions(), &problem, &summary);
  return {PoseFromParameters(x), PoseFromParameters(z)};
}

void ExpectSamePose(const Pose& a, const Pose& b, double tolerance, const std::string& what) {
  EXPECT_LT(so3::Distance(a.linear(), b.linear()), tolerance) << what;
  EXPECT_LT((a.translation() - b.translation()).norm(), tolerance * (1.0 + b.translation().norm()))
      << what;
}

// From 3° / 3 cm off the truth, with and without a robust loss (and a gross outlier for the robust
// ones): the optimum Ceres finds, to 1e-9 rad and 1e-9 relative in translation (1e-8 with a
// robust loss), and the inverse normal equations there (ml's covariance) to 1e-9 relative.
TEST(MinimizeLoopCost, ReachesTheOptimumCeresReaches) {
  Vector6d offset;
  offset << 3.0 * kRadiansPerDegree, -2.0 * kRadiansPerDegree, 1.0 * kRadiansPerDegree, 0.03, -0.02,
      0.01;
  for (RobustLoss kind : {RobustLoss::kNone, RobustLoss::kHuber, RobustLoss::kCauchy}) {
    const std::unique_ptr<ceres::LossFunction> loss = MakeLoss(kind, kOutlierLevelScale);
    for (const Case& c : Cases(kind != RobustLoss::kNone)) {
      const std::string what = c.name + ", loss " + std::string(RobustLossName(kind));
      const handeye::Solution start{c.truth.X * se3::Exp(offset), c.truth.Z * se3::Exp(-offset)};
      const handeye::Solution ours = MinimizeLoopCost(c.problem, c.whitening, loss.get(), start);
      const handeye::Solution reference = CeresMinimum(c, loss.get(), start);
      // Both stop when a step gains less than 1e-14 of the cost; with a robust loss the cost is
      // flatter about the optimum (down-weighted stations), which that leaves fixed only to a few
      // 1e-9 rad (the two differ by up to 2e-9 rad there, by rounding of the path).
      const double tolerance = kind == RobustLoss::kNone ? 1e-9 : 1e-8;
      ExpectSamePose(ours.X, reference.X, tolerance, what + ": X");
      ExpectSamePose(ours.Z, reference.Z, tolerance, what + ": Z");
      if (kind != RobustLoss::kNone) continue;  // robust weights move with the pose
      const Matrix12d ours_covariance =
          LinearizeLoopCost(c.problem, c.whitening, nullptr, ours).hessian.inverse();
      const Matrix12d reference_covariance =
          LinearizeLoopCost(c.problem, c.whitening, nullptr, reference).hessian.inverse();
      EXPECT_LT((ours_covariance - reference_covariance).norm(), 1e-9 * reference_covariance.norm())
          << what;
    }
  }
}

// The normal equations against central differences of the cost (independent of the analytic
// Jacobians): g is half the gradient of F, and without a robust loss H is the Gauss–Newton Hessian
// Σ (W J)ᵀ(W J) with J by differences of the residuals.
TEST(LinearizeLoopCost, GradientAndHessianMatchFiniteDifferences) {
  const Case c = Cases(true).front();
  Vector6d offset;
  offset << 0.02, -0.01, 0.03, 0.01, 0.02, -0.01;
  const handeye::Solution at{c.truth.X * se3::Exp(offset), c.truth.Z};
  auto moved = [&](int k, double h) {
    Vector6d e = Vector6d::Zero();
    e(k % 6) = h;
    return k < 6 ? handeye::Solution{at.X * se3::Exp(e), at.Z}
                 : handeye::Solution{at.X, at.Z * se3::Exp(e)};
  };
  constexpr double h = 1e-6;
  for (RobustLoss kind : {RobustLoss::kNone, RobustLoss::kHuber, RobustLoss::kCauchy}) {
    const std::unique_ptr<ceres::LossFunction> loss = MakeLoss(kind, kOutlierLevelScale);
    const LoopNormalEquations equations = LinearizeLoopCost(c.problem, c.whitening, loss.get(), at);
    EXPECT_NEAR(equations.cost, LoopCostValue(c.problem, c.whitening, loss.get(), at),
                1e-12 * equations.cost);
    for (int k = 0; k < 12; ++k) {
      const double numeric = (LoopCostValue(c.problem, c.whitening, loss.get(), moved(k, h)) -
                              LoopCostValue(c.problem, c.whitening, loss.get(), moved(k, -h))) /
                             (4.0 * h);
      EXPECT_NEAR(equations.gradient(k), numeric, 1e-5 * (1.0 + std::abs(numeric)))
          << RobustLossName(kind) << " axis " << k;
    }
  }
  Matrix12d hessian = Matrix12d::Zero();
  for (size_t i = 0; i < c.whitening.size(); ++i) {
    Matrix6x12d J;
    for (int k = 0; k < 12; ++k) {
      const handeye::Solution plus = moved(k, h), minus = moved(k, -h);
      J.col(k) = (LoopResidual(c.problem.A[i], c.problem.B[i], plus.X, plus.Z) -
                  LoopResidual(c.problem.A[i], c.problem.B[i], minus.X, minus.Z)) /
                 (2.0 * h);
    }
    hessian += (c.whitening[i] * J).transpose() * (c.whitening[i] * J);
  }
  const Matrix12d analytic = LinearizeLoopCost(c.problem, c.whitening, nullptr, at).hessian;
  EXPECT_LT((analytic - hessian).norm(), 1e-6 * hessian.norm());
}

// Noise-free data: the truth to 1e-9 from 5° / 5 cm off, both setups.
TEST(MinimizeLoopCost, NoiseFreeRecoversTheTruth) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const testing::Scene data = testing::ThesisCase(setup, 8, 75);
    const handeye::Problem problem = data.MeasuredProblem();
    const std::vector<Matrix6d> identity(problem.A.size(), Matrix6d::Identity());
    Vector6d offset;
    offset << 0.05, -0.06, 0.04, 0.05, -0.03, 0.02;
    const handeye::Solution result = MinimizeLoopCost(
        problem, identity, nullptr, {data.X * se3::Exp(offset), data.Z * se3::Exp(-offset)});
    ExpectSamePose(result.X, data.X, 1e-9, "X");
    ExpectSamePose(result.Z, data.Z, 1e-9, "Z");
  }
}

}  // namespace
}  // namespace hecal::estimation::internal
