#include "hecal/estimation/calibration_covariance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>

#include "testing/handeye_cases.h"

namespace hecal::estimation {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(Debug, EyeToHandUt) {
  const sim::SimulatedData data =
      testing::ThesisCase(handeye::Setup::kEyeToHand, 15, 5, 1.0 * kDeg, 1e-3);
  const handeye::Problem problem = data.MeasuredProblem();
  CalibrateOptions options;
  options.robot_sigma = options.camera_sigma = PoseSigma{1.0 * kDeg, 1e-3};
  const CalibrationResult result = Calibrate(problem, options);
  const StationNoise noise = StationNoise::Uniform(15, *options.robot_sigma, *options.camera_sigma);
  for (CovarianceMethod m : {CovarianceMethod::kLinear, CovarianceMethod::kUnscented,
                             CovarianceMethod::kMonteCarlo}) {
    CovarianceOptions c;
    c.method = m;
    c.samples = 500;
    const auto cov = PropagateCovariance(problem, result, options, noise, c);
    std::printf("%s: %s\n", std::string(CovarianceMethodName(m)).c_str(),
                std::to_string(0).c_str());
    std::cout << cov->X().diagonal().cwiseSqrt().transpose() << "\n";
  }
  std::cout << "analytic " << result.covariance->X().diagonal().cwiseSqrt().transpose() << "\n";
}

}  // namespace
}  // namespace hecal::estimation
