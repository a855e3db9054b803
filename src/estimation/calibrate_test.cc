#include "hecal/estimation/calibrate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/estimation/methods.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/se3.h"
#include "testing/handeye_cases.h"
#include "testing/options_validity.h"

namespace hecal::estimation {
namespace {

bool AnyWarningContains(const CalibrationResult& result, const std::string& text) {
  for (const std::string& warning : result.warnings)
    if (warning.find(text) != std::string::npos) return true;
  return false;
}

// Every method dispatches: closed-form ones return exactly handeye::SolveClosedForm's solution
// (their accuracy is tested in src/handeye), and every method has a covariance. The accuracy of
// every method through Calibrate is src/estimation/every_method_test.cc's.
TEST(Calibrate, EveryMethodDispatches) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    const testing::Scene data = testing::ThesisCase(setup, 8, 81);
    const handeye::Problem problem = data.MeasuredProblem();
    for (const MethodInfo& info : AllMethods()) {
      CalibrateOptions options;
      options.method = info.method;
      const CalibrationResult result = Calibrate(problem, options);
      EXPECT_EQ(result.method, info.method);
      ASSERT_EQ(result.residuals.size(), problem.A.size());
      ASSERT_TRUE(result.covariance.has_value()) << info.name;  // every method has one
      EXPECT_EQ(result.covariance->method, DefaultCovarianceMethod(info.method, problem.A.size()))
          << info.name;
      if (info.closed_form) {
        const handeye::Solution direct = handeye::SolveClosedForm(*info.closed_form, problem);
        EXPECT_TRUE(result.X.isApprox(direct.X, 1e-12)) << info.name;
        EXPECT_TRUE(result.Z.isApprox(direct.Z, 1e-12)) << info.name;
      }
    }
  }
}

TEST(Calibrate, MlReportsResidualsSigmasAndCovariance) {
  const PoseSigma sigma{0.5 * kRadiansPerDegree, 1e-3};
  const testing::Scene data =
      testing::ThesisCase(handeye::Setup::kEyeToHand, 15, 82, sigma.rotation, sigma.translation);
  const handeye::Problem problem = data.MeasuredProblem();
  const CalibrationResult estimated = Calibrate(problem, {});
  EXPECT_EQ(estimated.method, Method::kMl);
  EXPECT_TRUE(estimated.sigmas_estimated);
  EXPECT_TRUE(AnyWarningContains(estimated, "estimated from the residuals"));
  ASSERT_TRUE(estimated.covariance.has_value());
  EXPECT_EQ(estimated.covariance->method, CovarianceMethod::kLinear);
  EXPECT_EQ(estimated.covariance->solves, 0);  // ml's analytic information
  EXPECT_GT((estimated.covariance->X().block<3, 3>(0, 0).trace()), 0.0);
  // Residual summaries are consistent with the per-station values.
  double rotation2 = 0.0, whitened2 = 0.0;
  for (const StationResidual& r : estimated.residuals) {
    rotation2 += r.rotation * r.rotation;
    whitened2 += r.whitened * r.whitened;
    EXPECT_FALSE(r.outlier);
  }
  EXPECT_NEAR(estimated.rotation_rms, std::sqrt(rotation2 / 15.0), 1e-12);
  // Σ whitened² · 6 is the χ² of the fit: about 6n − 12 = 78 with the estimated noise.
  EXPECT_NEAR(6.0 * whitened2, 78.0, 25.0);

  CalibrateOptions given;
  given.robot_sigma = sigma;
  given.camera_sigma = sigma;
  const CalibrationResult known = Calibrate(problem, given);
  EXPECT_FALSE(known.sigmas_estimated);
  EXPECT_FALSE(AnyWarningContains(known, "estimated"));
  EXPECT_DOUBLE_EQ(known.robot_sigma.rotation, sigma.rotation);
  EXPECT_LT(testing::Error(known.X, estimated.X).rotation, 0.1 * kRadiansPerDegree);
}

// A station 5° / 20 mm off (10σ): rejected by default, listed with its residual, and the
// estimate equals the one without it; with reject_outliers = false it is flagged and kept.
TEST(Calibrate, RejectsACorruptedStationOrFlagsItWhenKept) {
  const PoseSigma sigma{0.5 * kRadiansPerDegree, 1e-3};
  testing::Scene data =
      testing::ThesisCase(handeye::Setup::kEyeInHand, 15, 83, sigma.rotation, sigma.translation);
  Vector6d gross;
  gross << 5.0 * kRadiansPerDegree, 0.0, 0.0, 0.0, 0.02, 0.0;
  data.T_base_gripper[9] = data.T_base_gripper[9] * se3::Exp(gross);
  handeye::Problem without = data.MeasuredProblem();
  without.A.erase(without.A.begin() + 9);
  without.B.erase(without.B.begin() + 9);
  for (const bool given : {false, true}) {
    CalibrateOptions options;
    if (given) options.robot_sigma = options.camera_sigma = sigma;
    const CalibrationResult result = Calibrate(data.MeasuredProblem(), options);
    ASSERT_EQ(result.rejected, std::vector<int>{9});
    ASSERT_EQ(result.rejected_residuals.size(), 1u);
    EXPECT_GT(result.rejected_residuals[0].whitened, 3.0);
    EXPECT_NEAR(result.rejected_residuals[0].rotation, 5.0 * kRadiansPerDegree,
                2.0 * kRadiansPerDegree);
    EXPECT_EQ(result.residuals.size(), 14u);
    for (const StationResidual& r : result.residuals) EXPECT_FALSE(r.outlier);
    EXPECT_TRUE(AnyWarningContains(result, "station 10 rejected"));
    EXPECT_TRUE(result.outlier_rejection);
    const CalibrationResult reference = Calibrate(without, options);
    EXPECT_LT(testing::Error(result.X, reference.X).rotation, 1e-9);
    EXPECT_LT(testing::Error(result.X, reference.X).translation, 1e-9);

    options.reject_outliers = false;
    const CalibrationResult kept = Calibrate(data.MeasuredProblem(), options);
    EXPECT_TRUE(kept.rejected.empty());
    for (int i = 0; i < 15; ++i) EXPECT_EQ(kept.residuals[i].outlier, i == 9) << i;
    EXPECT_GT(kept.residuals[9].whitened, 3.0);
    EXPECT_TRUE(AnyWarningContains(kept, "station 10 has"));
    EXPECT_TRUE(AnyWarningContains(kept, "outlier rejection is off"));
  }
}

TEST(Calibrate, RejectsBadOptionsAndDegenerateData) {
  const testing::Scene data = testing::ThesisCase(handeye::Setup::kEyeInHand, 6, 84);
  const handeye::Problem problem = data.MeasuredProblem();
  CalibrateOptions negative;
  negative.robot_sigma = PoseSigma{-1.0, 0.001};
  EXPECT_THROW(Calibrate(problem, negative), InputError);
  CalibrateOptions zero;
  zero.robot_sigma = PoseSigma{0.0, 0.001};
  zero.camera_sigma = PoseSigma{0.0, 0.001};
  EXPECT_THROW(Calibrate(problem, zero), InputError);
  CalibrateOptions robust_closed_form;
  robust_closed_form.method = Method::kParkMartin;
  robust_closed_form.robust_loss = RobustLoss::kHuber;
  EXPECT_TRUE(AnyWarningContains(Calibrate(problem, robust_closed_form), "ml only"));
  handeye::Problem two = problem;
  two.A.resize(2);
  two.B.resize(2);
  EXPECT_THROW(Calibrate(two, {}), DegenerateError);
}

TEST(CalibrateOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const CalibrateOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  CalibrateOptions given = defaults;
  given.robot_sigma = PoseSigma{std::numbers::pi, 1.0};  // the largest: 180 deg, 1000 mm
  given.camera_sigma = PoseSigma{0.0, 0.0};              // exact camera, noisy robot
  EXPECT_TRUE(testing::IsValidOptions(given));
  EXPECT_TRUE(RefusesNaming(defaults, "CalibrateOptions.robot_sigma", [](auto& o) {
    o.robot_sigma = PoseSigma{-1e-3, 1e-3};
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "CalibrateOptions.robot_sigma", [](auto& o) {
    o.robot_sigma = PoseSigma{1e-3, 1.001};
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "CalibrateOptions.camera_sigma", [](auto& o) {
    o.camera_sigma = PoseSigma{3.2, 1e-3};
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "CalibrateOptions.camera_sigma", [](auto& o) {
    o.camera_sigma = PoseSigma{std::nan(""), 1e-3};
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "CalibrateOptions.robot_sigma", [](auto& o) {
    o.robot_sigma = PoseSigma{0.0, 1e-3};  // no rotation noise on either side: singular
    o.camera_sigma = PoseSigma{0.0, 1e-3};
  }));
  EXPECT_TRUE(RefusesNaming(defaults, "CalibrateOptions.robust_scale",
                            [](auto& o) { o.robust_scale = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "CovarianceOptions.samples",
                            [](auto& o) { o.covariance.samples = 1; }));
  EXPECT_TRUE(RefusesNaming(defaults, "ConsensusOptions.max_hypotheses",
                            [](auto& o) { o.consensus.max_hypotheses = 0; }));
  // Calibrate refuses them before solving.
  const testing::Scene data = testing::ThesisCase(handeye::Setup::kEyeInHand, 6, 84);
  CalibrateOptions bad;
  bad.robust_scale = -1.0;
  EXPECT_THROW(Calibrate(data.MeasuredProblem(), bad), InputError);
}

}  // namespace
}  // namespace hecal::estimation
