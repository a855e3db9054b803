// The pivot study: see pivot_study.h.
#include "hecal/jobs/pivot_study.h"

#include <random>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/core/split_mix.h"
#include "hecal/estimation/pivot.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/uncertainty/consistency.h"

namespace hecal::jobs {
namespace {

struct Tally {
  int trials = 0, failures = 0, covered1 = 0, covered2 = 0;
  double tip2 = 0.0, pivot2 = 0.0, nees = 0.0, tip_nees = 0.0;
};

void Add(const sim::PivotScene& scene, const estimation::PivotOptions& options, Tally& tally) {
  estimation::PivotResult result;
  try {
    result = estimation::CalibratePivot(scene.T_base_flange, options);
  } catch (const DegenerateError&) {
    ++tally.failures;
    return;
  }
  Vector6d error;
  error << result.tip - scene.tip, result.pivot - scene.pivot;
  const double nees = uncertainty::Nees(error, result.covariance);
  ++tally.trials;
  tally.tip2 += error.head<3>().squaredNorm();
  tally.pivot2 += error.tail<3>().squaredNorm();
  tally.nees += nees;
  tally.tip_nees += uncertainty::Nees(error.head<3>(), result.covariance.topLeftCorner<3, 3>());
  tally.covered1 += nees <= uncertainty::ChiSquareQuantile(uncertainty::SigmaProbability(1), 6);
  tally.covered2 += nees <= uncertainty::ChiSquareQuantile(uncertainty::SigmaProbability(2), 6);
}

PivotStudyRow Row(const study::NoiseLevel& sigma, int stations, bool estimated,
                  const Tally& tally) {
  PivotStudyRow row;
  row.sigma = sigma;
  row.stations = stations;
  row.estimated = estimated;
  row.trials = tally.trials;
  row.failures = tally.failures;
  if (tally.trials == 0) return row;
  const double n = tally.trials;
  row.tip_rmse = std::sqrt(tally.tip2 / n);
  row.pivot_rmse = std::sqrt(tally.pivot2 / n);
  row.mean_nees = tally.nees / n;
  row.nees_low = uncertainty::ChiSquareQuantile(0.025, 6 * n) / n;
  row.nees_high = uncertainty::ChiSquareQuantile(0.975, 6 * n) / n;
  row.mean_tip_nees = tally.tip_nees / n;
  row.coverage_1sigma = tally.covered1 / n;
  row.coverage_2sigma = tally.covered2 / n;
  return row;
}

}  // namespace

bool PivotStudyOptions::IsValid(std::string* why) const {
  if (sigmas.empty()) {
    return Invalid(why, "PivotStudyOptions.sigmas", "needs at least one noise level",
                   "give --sigma, e.g. 0.1 (0.1 mm and 0.1 deg per axis)");
  }
  for (const study::NoiseLevel& level : sigmas) {
    if (!(level.mm > 0.0 && level.mm <= 1000.0 && level.deg >= 0.0 && level.deg <= 180.0)) {
      return Invalid(why, "PivotStudyOptions.sigmas",
                     "every level needs 0 < mm <= 1000 and 0 <= deg <= 180 (the fit told the "
                     "noise weighs by the translation noise)",
                     "give levels such as 0.1 or 0.05/0.02 (MM/DEG)");
    }
  }
  for (int count : stations) {
    if (count < 3 || count > 100000) {
      return Invalid(why, "PivotStudyOptions.stations", "must be 3 … 100000 each",
                     "give the orientations per pivot, e.g. 20");
    }
  }
  if (stations.empty()) {
    return Invalid(why, "PivotStudyOptions.stations", "needs at least one station count",
                   "give --stations, e.g. 20");
  }
  if (trials < 1 || trials > 100000) {
    return Invalid(why, "PivotStudyOptions.trials", "must be 1 … 100000",
                   "give the number of simulated pivots per setting (default 200)");
  }
  if (!(max_tilt_deg >= 5.0 && max_tilt_deg <= 90.0)) {
    return Invalid(why, "PivotStudyOptions.max_tilt_deg", "must be 5 … 90 degrees",
                   "give the tilt about each flange axis (default 30)");
  }
  return true;
}

sim::PivotScene PivotStudyTrial(const PivotStudyOptions& options, const study::NoiseLevel& sigma,
                                int stations, int trial) {
  sim::PivotSceneOptions scene;
  scene.stations = stations;
  scene.max_tilt = options.max_tilt_deg * kRadiansPerDegree;
  scene.rotation_sigma = sigma.deg * kRadiansPerDegree;
  scene.translation_sigma = sigma.mm * 1e-3;
  std::mt19937_64 rng(SplitMix64(options.seed + static_cast<std::uint64_t>(trial)));
  return sim::SimulatePivot(scene, rng);
}

PivotStudy RunPivotStudy(const PivotStudyOptions& options) {
  RequireValid(options);
  PivotStudy study{.options = options, .rows = {}};
  for (const study::NoiseLevel& sigma : options.sigmas) {
    for (int stations : options.stations) {
      estimation::PivotOptions given, estimated;
      given.sigma = estimation::PoseSigma{sigma.deg * kRadiansPerDegree, sigma.mm * 1e-3};
      given.reject_outliers = estimated.reject_outliers = options.reject_outliers;
      Tally given_tally, estimated_tally;
      for (int trial = 0; trial < options.trials; ++trial) {
        const sim::PivotScene scene = PivotStudyTrial(options, sigma, stations, trial);
        Add(scene, given, given_tally);
        Add(scene, estimated, estimated_tally);
      }
      study.rows.push_back(Row(sigma, stations, false, given_tally));
      study.rows.push_back(Row(sigma, stations, true, estimated_tally));
    }
  }
  return study;
}

}  // namespace hecal::jobs
