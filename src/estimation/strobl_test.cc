#include "hecal/estimation/strobl.h"

#include <gtest/gtest.h>

#include <cmath>

#include "hecal/estimation/bound.h"
#include "hecal/estimation/initialization.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/se3.h"
#include "testing/handeye_cases.h"
#include "testing/options_validity.h"

namespace hecal::estimation {
namespace {

class StroblTest : public ::testing::TestWithParam<handeye::Setup> {};

// Noise-free recovery from the closed-form starts (as `--method strobl` runs it) is
// src/estimation/every_method_test.cc's; here from a rough start alone.
TEST_P(StroblTest, NoiseFreeConvergesFromAPerturbedStart) {
  const testing::Scene data = testing::ThesisCase(GetParam(), 6, 74);
  Vector6d offset;
  offset << 0.05, -0.06, 0.04, 0.05, -0.03, 0.02;
  const StroblResult result = RefineStrobl(
      data.MeasuredProblem(), {{data.X * se3::Exp(offset), data.Z * se3::Exp(-offset)}});
  EXPECT_LT(testing::Error(result.X, data.X).rotation, 1e-9);
  EXPECT_LT(testing::Error(result.X, data.X).translation, 1e-9);
}

// With noise, the automatic weights are the RMS errors at the optimum, and the estimate is a
// sensible one: within 2× the first-order bound on the thesis protocol (it ignores the lever-arm
// structure of the noise, so it is not expected to reach the bound like ml).
TEST_P(StroblTest, AutomaticWeightingAndAccuracyWithNoise) {
  const PoseSigma sigma{1.0 * kRadiansPerDegree, 1e-3};
  double error2 = 0.0, bound2 = 0.0;
  for (int trial = 0; trial < 20; ++trial) {
    const testing::Scene data =
        testing::ThesisCase(GetParam(), 15, 7000 + trial, sigma.rotation, sigma.translation);
    const handeye::Problem problem = data.MeasuredProblem();
    const StroblResult result = RefineStrobl(problem, Solutions(InitialSolutions(problem)));
    double rotation2 = 0.0;
    for (size_t i = 0; i < problem.A.size(); ++i) {
      const Pose E = result.Z.inverse() * problem.A[i] * result.X * problem.B[i];
      rotation2 += se3::Log(E).head<3>().squaredNorm();
    }
    EXPECT_NEAR(result.sigma_rotation, std::sqrt(rotation2 / problem.A.size()), 1e-9);
    EXPECT_GE(result.iterations, 1);
    const AccuracyBound bound = FirstOrderBound(
        handeye::MakeProblem(data.setup, data.T_base_gripper_true, data.T_camera_target_true),
        data.X, data.Z, sigma, sigma);
    error2 += std::pow(testing::Error(result.X, data.X).rotation, 2);
    bound2 += bound.rotation_rmse_X * bound.rotation_rmse_X;
  }
  EXPECT_LT(std::sqrt(error2 / bound2), 2.0);
}

INSTANTIATE_TEST_SUITE_P(BothSetups, StroblTest,
                         ::testing::Values(handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand));

TEST(StroblOptions, IsValidNamesTheField) {
  EXPECT_TRUE(testing::IsValidOptions(StroblOptions{}));
  EXPECT_TRUE(testing::RefusesNaming(StroblOptions{}, "StroblOptions.max_iterations",
                                     [](auto& o) { o.max_iterations = 0; }));
}

}  // namespace
}  // namespace hecal::estimation
