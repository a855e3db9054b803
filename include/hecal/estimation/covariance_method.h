// How a calibration's covariance is computed (calibration_covariance.h): the method, its
// options and the result that CalibrationResult carries.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/estimation/methods.h"
#include "hecal/geometry/types.h"
#include "hecal/uncertainty/monte_carlo.h"
#include "hecal/uncertainty/unscented.h"

namespace hecal::estimation {

// kNone: no covariance (studies that do not need one; the CLI's calibrate never uses it).
enum class CovarianceMethod { kNone, kLinear, kUnscented, kMonteCarlo, kInformation };
// "none" | "linear" | "unscented" | "montecarlo" | "information"; nullopt otherwise.
std::optional<CovarianceMethod> ParseCovarianceMethod(std::string_view text);
std::string_view CovarianceMethodName(CovarianceMethod method);

// Above this many stations the closed forms and strobl default to kInformation: the UT costs
// 24n + 1 solves of a method that is itself O(n) (O(n²) with all station pairs, motion.h) and a
// dense 12n × 12n input covariance — tsai-lenz at n = 100: 1 s, n = 200: 7 s, n = 10⁴: 115 GB.
inline constexpr size_t kMaxUnscentedStations = 100;
// The most stations kLinear-through-the-solver, kUnscented and kMonteCarlo accept: they need the
// dense 12n × 12n input covariance (and its square root), 0.3 GB at 500 stations, 115 GB at 10⁴.
// Above it only kInformation (and ml's kLinear, its analytic information) are offered.
inline constexpr size_t kMaxPropagatedStations = 500;

// kLinear for ml (its analytic Gauss–Newton information: free and validated;
// MethodInfo::analytic_covariance, methods.h). For every other method kUnscented up to
// kMaxUnscentedStations stations (the contour paper's approach; a numeric linearisation costs the
// same solves), kInformation above.
CovarianceMethod DefaultCovarianceMethod(Method method, size_t stations);

// The most Monte Carlo samples (10^5 solves of two poses each).
inline constexpr int kMaxCovarianceSamples = 100000;

struct CovarianceOptions {
  std::optional<CovarianceMethod> method;  // nullopt: DefaultCovarianceMethod
  int samples = 5000;                      // kMonteCarlo: 2 … kMaxCovarianceSamples
  std::uint64_t seed = 1;                  // kMonteCarlo
  int threads = 0;                         // 0: every core; at most kMaxThreads (core/limits.h)
  uncertainty::UnscentedParameters unscented;

  // core/options_check.h: false naming CovarianceOptions.samples or .threads outside the ranges
  // above. Calibrate and RunStudy require it.
  bool IsValid(std::string* why) const;
};
// Throws InputError (source "CovarianceOptions.method") when `method` for `solver` needs the dense
// input covariance and there are more than kMaxPropagatedStations stations. Calibrate calls it
// before solving, PropagateCovariance again.
void CheckCovarianceFits(CovarianceMethod method, Method solver, size_t stations);

struct CalibrationCovariance {
  CovarianceMethod method = CovarianceMethod::kLinear;
  Eigen::Matrix<double, 12, 12> covariance;  // (δX, δZ), right perturbations, (ω, v) each
  int solves = 0;                            // solver runs (0: an analytic information matrix)
  // kMonteCarlo only.
  int samples = 0;   // that succeeded
  int failures = 0;  // samples whose solve threw or was not finite (left out)
  std::string first_failure;
  Eigen::Matrix<double, 12, 1> sd_std_error = Eigen::Matrix<double, 12, 1>::Zero();

  Matrix6d X() const { return covariance.topLeftCorner<6, 6>(); }
  Matrix6d Z() const { return covariance.bottomRightCorner<6, 6>(); }
};

// A Monte Carlo run over (X, Z) as a CalibrationCovariance.
CalibrationCovariance FromMonteCarlo(const uncertainty::MonteCarloMoments<std::vector<Pose>>& mc);

// The warning for failed Monte Carlo samples ("" when none failed).
std::string FailedSamplesWarning(const CalibrationCovariance& covariance);

}  // namespace hecal::estimation
