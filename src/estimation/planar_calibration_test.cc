// Calibration of planar robots with one component of X's translation given (handeye/planar.h):
// the observable part at the first-order bound, and the degenerate message without the fix.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "hecal/core/error.h"
#include "hecal/estimation/bound.h"
#include "hecal/estimation/calibrate.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/se3.h"
#include "hecal/sim/planar_robot.h"
#include "testing/thrown.h"

namespace hecal::estimation {
namespace {

constexpr double kSigmaMm = 0.2;
constexpr double kSigmaDeg = 0.2;

sim::NoiseModel Noise() {
  sim::NoiseModel noise;
  noise.rotation_sigma = kSigmaDeg * kRadiansPerDegree;
  noise.translation_sigma = kSigmaMm * 1e-3;
  return noise;
}

PoseSigma Sigma() { return {kSigmaDeg * kRadiansPerDegree, kSigmaMm * 1e-3}; }

TEST(PlanarCalibration, WithoutTheFixTheMessageNamesTheComponentAndTheFlag) {
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    std::mt19937_64 rng(11);
    const sim::PlanarScene scene = sim::DrawPlanarScene(setup, 15, Noise(), Noise(), rng);
    const DegenerateError error =
        testing::Thrown<DegenerateError>([&] { Calibrate(scene.measured, CalibrateOptions()); });
    const std::string text = error.what();
    EXPECT_NE(text.find("--fix tz=VALUE"), std::string::npos) << text;
    EXPECT_NE(text.find("translation of X"), std::string::npos) << text;
  }
}

TEST(PlanarCalibration, OtherMethodsRefuseTheFix) {
  CalibrateOptions options;
  options.method = Method::kParkMartin;
  options.fix = handeye::TranslationFix{2, 0.1};
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_NE(why.find("CalibrateOptions.fix"), std::string::npos) << why;
}

// 200 calibrations of a 15-station SCARA at 0.2 mm / 0.2° on every pose, tz given its true
// value: the errors of the observable part against the constrained first-order bound, and the
// reported covariance's NEES over the 11 observable directions.
TEST(PlanarCalibration, TheObservablePartIsAtTheBound) {
  constexpr int kTrials = 200;
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    std::mt19937_64 rng(21);
    double squared[4] = {0, 0, 0, 0};
    double bound_squared[4] = {0, 0, 0, 0};
    double nees = 0.0;
    for (int trial = 0; trial < kTrials; ++trial) {
      const sim::PlanarScene scene = sim::DrawPlanarScene(setup, 15, Noise(), Noise(), rng);
      CalibrateOptions options;
      options.fix = handeye::TranslationFix{2, scene.X.translation().z()};
      options.robot_sigma = Sigma();
      options.camera_sigma = Sigma();
      options.model_check = false;
      options.reject_outliers = false;
      const CalibrationResult result = Calibrate(scene.measured, options);
      ASSERT_TRUE(result.fixed);
      EXPECT_NEAR(result.X.translation().z(), scene.X.translation().z(), 1e-12);
      Eigen::Matrix<double, 12, 1> error;
      error << se3::Log(scene.X.inverse() * result.X), se3::Log(scene.Z.inverse() * result.Z);
      squared[0] += error.segment<3>(0).squaredNorm();
      squared[1] += (result.X.translation() - scene.X.translation()).squaredNorm();
      squared[2] += error.segment<3>(6).squaredNorm();
      squared[3] += (result.Z.translation() - scene.Z.translation()).squaredNorm();
      const AccuracyBound bound =
          FirstOrderBound(scene.truth, scene.X, scene.Z, Sigma(), Sigma(), *result.fixed);
      bound_squared[0] += std::pow(bound.rotation_rmse_X, 2);
      bound_squared[1] += std::pow(bound.translation_rmse_X, 2);
      bound_squared[2] += std::pow(bound.rotation_rmse_Z, 2);
      bound_squared[3] += std::pow(bound.translation_rmse_Z, 2);
      const Eigen::Matrix<double, 12, 12> pseudo =
          result.covariance->covariance.completeOrthogonalDecomposition().pseudoInverse();
      nees += error.dot(pseudo * error);
    }
    const char* names[4] = {"X rotation", "X translation", "Z rotation", "Z translation"};
    for (int k = 0; k < 4; ++k) {
      const double ratio = std::sqrt(squared[k] / bound_squared[k]);
      std::printf("%s %s: RMSE / bound = %.3f\n", std::string(handeye::SetupName(setup)).c_str(),
                  names[k], ratio);
      EXPECT_LT(ratio, 1.15) << names[k];
      EXPECT_GT(ratio, 0.85) << names[k];
    }
    // 11 observable directions: the mean NEES of 200 trials is 11 ± 0.33 (1σ); ±1.0 is 3σ.
    std::printf("%s NEES (11 directions): %.2f\n", std::string(handeye::SetupName(setup)).c_str(),
                nees / kTrials);
    EXPECT_NEAR(nees / kTrials, 11.0, 1.0);
  }
}

}  // namespace
}  // namespace hecal::estimation
