// The UT against a 5000-sample Monte Carlo on the same calibrations (label "slow";
// about a minute on 2 cores). Thesis protocol, σ = 1 mm / 1° on robot and camera, both setups,
// ml and park-martin, n = 5, 10, 15, 20 stations, 3 data sets each. Prints the largest per-axis
// |σ_UT/σ_MC − 1| of X and Z per case; asserts it below 10% (+ 3 standard errors of σ_MC, about
// 1% each) for n ≥ 10, the criterion of docs/uncertainty.md. n = 5 is printed as well (in the
// run of docs/uncertainty.md it agrees as closely: ≤ 2.5%).
#include <gtest/gtest.h>

#include <cstdio>

#include "hecal/estimation/calibration_covariance.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/uncertainty/consistency.h"
#include "testing/handeye_cases.h"

namespace hecal::estimation {
namespace {
constexpr const char* kAxes[] = {"rx", "ry", "rz", "tx", "ty", "tz"};

TEST(UnscentedVsMonteCarlo, WithinTenPercentFromTenStations) {
  const PoseSigma sigma{1.0 * kRadiansPerDegree, 1e-3};
  std::printf("setup         method        n  seed  max|UT/MC-1|  (axis)\n");
  for (handeye::Setup setup : {handeye::Setup::kEyeInHand, handeye::Setup::kEyeToHand}) {
    for (Method method : {Method::kMl, Method::kParkMartin}) {
      for (int n : {5, 10, 15, 20}) {
        for (uint64_t seed : {101u, 102u, 103u}) {
          const testing::Scene data =
              testing::ThesisCase(setup, n, seed, sigma.rotation, sigma.translation);
          const handeye::Problem problem = data.MeasuredProblem();
          CalibrateOptions options;
          options.method = method;
          options.robot_sigma = options.camera_sigma = sigma;
          options.covariance.method = CovarianceMethod::kNone;
          const CalibrationResult result = Calibrate(problem, options);
          const StationNoise noise = StationNoise::Uniform(static_cast<size_t>(n), sigma, sigma);
          CovarianceOptions ut_options, mc_options;
          ut_options.method = CovarianceMethod::kUnscented;
          mc_options.method = CovarianceMethod::kMonteCarlo;
          mc_options.samples = 5000;
          mc_options.seed = seed;
          const CalibrationCovariance ut =
              *PropagateCovariance(problem, result, options, noise, ut_options);
          const CalibrationCovariance mc =
              *PropagateCovariance(problem, result, options, noise, mc_options);
          const Eigen::VectorXd deviation =
              (uncertainty::StdRatio(ut.covariance, mc.covariance).array() - 1.0).abs();
          Eigen::Index worst_axis = 0;
          const double worst = deviation.maxCoeff(&worst_axis);
          for (int j = 0; j < 12; ++j) {
            const double ut_sd = std::sqrt(ut.covariance(j, j));
            const double mc_sd = std::sqrt(mc.covariance(j, j));
            if (n >= 10) {
              EXPECT_NEAR(ut_sd, mc_sd, 0.10 * mc_sd + 3.0 * mc.sd_std_error(j))
                  << handeye::SetupName(setup) << " " << Info(method).name << " n=" << n << " seed "
                  << seed << " axis " << j;
            }
          }
          std::printf("%-13s %-12s %2d  %4d  %11.1f%%  (%s %s)\n",
                      std::string(handeye::SetupName(setup)).c_str(),
                      std::string(Info(method).name).c_str(), n, static_cast<int>(seed),
                      100.0 * worst, worst_axis < 6 ? "X" : "Z", kAxes[worst_axis % 6]);
        }
      }
    }
  }
}

}  // namespace
}  // namespace hecal::estimation
