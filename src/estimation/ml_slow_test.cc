// The statistical acceptance study of docs/thesis-study.md, label "slow": the thesis protocol
// (docs/thesis-study.md), σ = 1 mm / 1° per component on robot AND camera, 200 trials per setting.
//  - n = 15: ml's rotation and translation RMSE of X within 10% of the first-order bound
//    (bound.h; RMSE_bound = sqrt(mean over trials of each trial's bound²)), with the true
//    sigmas given and with the sigmas estimated from the residuals;
//  - n = 5, 10, 15, 20: no trial worse than 10× its own bound.
// Statistical margin: the RMSE/bound ratio over 200 trials has a relative standard error of
// about 0.82/(2√200) ≈ 2.9%, so ±10% is a 3.4σ band around an estimator that attains the bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "hecal/estimation/bound.h"
#include "hecal/estimation/initialization.h"
#include "hecal/estimation/ml.h"
#include "hecal/geometry/angle_units.h"
#include "testing/handeye_cases.h"

namespace hecal::estimation {
namespace {
constexpr int kTrials = 200;

struct Figures {
  double rotation = 0, translation = 0;              // RMSE
  double bound_rotation = 0, bound_translation = 0;  // sqrt(mean bound²)
  double worst = 0;                                  // max error / own bound
};

Figures Study(handeye::Setup setup, int stations, bool sigmas_given, uint64_t seed) {
  const PoseSigma sigma{1.0 * kRadiansPerDegree, 1e-3};
  MlOptions options;
  if (sigmas_given) options.robot_sigma = options.camera_sigma = sigma;
  Figures f;
  for (int trial = 0; trial < kTrials; ++trial) {
    const testing::Scene data =
        testing::ThesisCase(setup, stations, seed + trial, sigma.rotation, sigma.translation);
    const handeye::Problem problem = data.MeasuredProblem();
    const AccuracyBound bound = FirstOrderBound(
        handeye::MakeProblem(setup, data.T_base_gripper_true, data.T_camera_target_true), data.X,
        data.Z, sigma, sigma);
    const MlResult result = RefineMl(problem, Solutions(InitialSolutions(problem)), options);
    const testing::PoseError error = testing::Error(result.X, data.X);
    f.rotation += error.rotation * error.rotation;
    f.translation += error.translation * error.translation;
    f.bound_rotation += bound.rotation_rmse_X * bound.rotation_rmse_X;
    f.bound_translation += bound.translation_rmse_X * bound.translation_rmse_X;
    f.worst = std::max({f.worst, error.rotation / bound.rotation_rmse_X,
                        error.translation / bound.translation_rmse_X});
  }
  for (double* v : {&f.rotation, &f.translation, &f.bound_rotation, &f.bound_translation})
    *v = std::sqrt(*v / kTrials);
  std::printf(
      "%s n=%d sigmas %s: ml %.4f° / %.3f mm, bound %.4f° / %.3f mm, ratio %.3f / %.3f, "
      "worst trial %.2f× its bound\n",
      setup == handeye::Setup::kEyeInHand ? "eye-in-hand" : "eye-to-hand", stations,
      sigmas_given ? "given" : "estimated", f.rotation / kRadiansPerDegree, f.translation * 1e3,
      f.bound_rotation / kRadiansPerDegree, f.bound_translation * 1e3,
      f.rotation / f.bound_rotation, f.translation / f.bound_translation, f.worst);
  return f;
}

class MlStudy : public ::testing::TestWithParam<handeye::Setup> {};

TEST_P(MlStudy, RmseWithinTenPercentOfTheBoundAtFifteenStations) {
  for (const bool given : {true, false}) {
    const Figures f = Study(GetParam(), 15, given, 1000);
    EXPECT_NEAR(f.rotation / f.bound_rotation, 1.0, 0.10) << (given ? "given" : "estimated");
    EXPECT_NEAR(f.translation / f.bound_translation, 1.0, 0.10) << (given ? "given" : "estimated");
    EXPECT_LT(f.worst, 10.0);
  }
}

TEST_P(MlStudy, NoTrialWorseThanTenTimesTheBound) {
  for (const int stations : {5, 10, 20}) {
    EXPECT_LT(Study(GetParam(), stations, false, 3000 + 1000 * stations).worst, 10.0)
        << stations << " stations";
  }
}

INSTANTIATE_TEST_SUITE_P(BothSetups, MlStudy,
                         ::testing::Values(handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand));

}  // namespace
}  // namespace hecal::estimation
