// Calibrate at 2·10⁴ stations (thesis protocol, eye-in-hand, σ = 1 mm / 1° per component on
// robot and camera, sigmas given, no outlier rejection), the linear-memory paths of
// docs/speed.md (Scale): a motion-based closed form on the subsampled station pairs (motion.h),
// shah on the absolute poses, and ml started from closed forms on 500 stations
// (initialization.h). Each X is compared with the first-order bound at the true poses
// (bound.h: ~0.015° / 0.03 mm here). The factors are what the methods attain, with margin:
// ml is efficient (its error is a draw of about the bound); tsai-lenz's translation is ~3× less
// efficient and shah's ~20× (it weights every station's translation equally, whatever its
// lever arm: docs/accuracy.md). The closed forms get the information covariance (no solves).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "hecal/estimation/bound.h"
#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/calibration_covariance.h"
#include "hecal/geometry/angle_units.h"
#include "testing/handeye_cases.h"

namespace hecal::estimation {
namespace {

TEST(CalibrateAtScale, TwentyThousandStationsAtTheAccuracyTheDataAllow) {
  const PoseSigma sigma{1.0 * kRadiansPerDegree, 1e-3};
  const int n = 20000;
  const testing::Scene data =
      testing::ThesisCase(handeye::Setup::kEyeInHand, n, 2026, sigma.rotation, sigma.translation);
  const handeye::Problem problem = data.MeasuredProblem();
  const AccuracyBound bound = FirstOrderBound(
      handeye::MakeProblem(data.setup, data.T_base_gripper_true, data.T_camera_target_true), data.X,
      data.Z, sigma, sigma);
  struct Expectation {
    Method method;
    double rotation;     // error / bound, at most
    double translation;  // error / bound, at most
    CovarianceMethod covariance;
  };
  for (const Expectation& e :
       {Expectation{Method::kTsaiLenz, 4.0, 8.0, CovarianceMethod::kInformation},
        Expectation{Method::kShah, 4.0, 60.0, CovarianceMethod::kInformation},
        Expectation{Method::kMl, 4.0, 4.0, CovarianceMethod::kLinear}}) {
    CalibrateOptions options;
    options.method = e.method;
    options.robot_sigma = options.camera_sigma = sigma;
    options.reject_outliers = false;
    const CalibrationResult result = Calibrate(problem, options);
    const testing::PoseError error = testing::Error(result.X, data.X);
    const std::string name(Info(e.method).name);
    std::printf("%-10s error / bound: rotation %.2f, translation %.2f\n", name.c_str(),
                error.rotation / bound.rotation_rmse_X,
                error.translation / bound.translation_rmse_X);
    EXPECT_LT(error.rotation, e.rotation * bound.rotation_rmse_X) << name;
    EXPECT_LT(error.translation, e.translation * bound.translation_rmse_X) << name;
    ASSERT_TRUE(result.covariance.has_value()) << name;
    EXPECT_EQ(result.covariance->method, e.covariance) << name;
    EXPECT_EQ(result.covariance->solves, 0) << name;
  }
}

}  // namespace
}  // namespace hecal::estimation
