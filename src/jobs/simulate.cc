// The job of `hecal simulate`: see simulate.h.
#include "hecal/jobs/simulate.h"

#include <cmath>

#include "hecal/core/options_check.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/study/study_csv.h"

namespace hecal::jobs {
namespace {

std::string Range(std::int64_t low, std::int64_t high) {
  return std::to_string(low) + " to " + std::to_string(high);
}

// "'V' is outside the range LOW to HIGH" for the first item of `values` outside it, else "".
// Appended piece by piece: a chain of `+` trips GCC 12's -Wrestrict false positive (GCC bug
// 105329).
std::string FirstOutside(const std::vector<int>& values, int low, int high) {
  std::string message;
  for (int value : values) {
    if (value < low || value > high) {
      message += '\'';
      message += std::to_string(value);
      message += "' is outside the range ";
      message += Range(low, high);
      break;
    }
  }
  return message;
}

}  // namespace

bool SimulateOptions::IsValid(std::string* why) const {
  const auto empty = [&](const char* field, bool is_empty) {
    return is_empty && !Invalid(why, std::string("SimulateOptions.") + field,
                                "the sweep has no value", "give at least one value");
  };
  if (empty("setups", setups.empty()) || empty("stations", stations.empty()) ||
      empty("noise_on", noise_on.empty()) || empty("noise", noise.empty()) ||
      empty("sigmas", sigmas.empty()) || empty("outliers", outliers.empty()) ||
      empty("robot_scales", robot_scales.empty())) {
    return false;
  }
  if (methods.empty()) {
    return Invalid(why, "SimulateOptions.methods", "no method selected",
                   "name one or more methods, or all");
  }
  if (const std::string bad = FirstOutside(stations, kMinStations, kMaxStations); !bad.empty()) {
    return Invalid(why, "SimulateOptions.stations", bad, "e.g. 10,20,50");
  }
  if (const std::string bad = FirstOutside(outliers, 0, kMaxStations); !bad.empty()) {
    return Invalid(why, "SimulateOptions.outliers", bad, "e.g. 0,1,2");
  }
  for (const study::NoiseLevel& level : sigmas) {
    if (!(level.mm >= 0.0 && level.mm <= kMaxSigmaMm) ||
        !(level.deg >= 0.0 && level.deg <= kMaxSigmaDeg)) {
      return Invalid(why, "SimulateOptions.sigmas",
                     "noise levels must be 0 to " + study::FormatNumber(kMaxSigmaMm) +
                         " mm and 0 to " + study::FormatNumber(kMaxSigmaDeg) +
                         " deg per axis, got " + study::FormatNumber(level.mm) + " mm / " +
                         study::FormatNumber(level.deg) + " deg",
                     "give the standard deviation of one axis in mm and degrees, e.g. 0.5/0.1");
    }
  }
  for (double scale : robot_scales) {
    if (!(scale > 0.0) || !(scale <= kMaxRobotScale)) {
      return Invalid(why, "SimulateOptions.robot_scales",
                     "'" + study::FormatNumber(scale) + "' is not a number above 0 and at most " +
                         study::FormatNumber(kMaxRobotScale),
                     "e.g. 1,5");
    }
    for (const study::NoiseLevel& level : sigmas) {
      if (level.mm * scale > kMaxSigmaMm || level.deg * scale > kMaxSigmaDeg) {
        return Invalid(why, "SimulateOptions.robot_scales",
                       "the robot noise (the noise level times the robot scale) must stay within " +
                           study::FormatNumber(kMaxSigmaMm) + " mm and " +
                           study::FormatNumber(kMaxSigmaDeg) + " deg per axis",
                       "give a smaller robot scale or noise level");
      }
    }
  }
  if (trials < 1 || trials > kMaxTrials) {
    return Invalid(
        why, "SimulateOptions.trials",
        "must be a whole number from " + Range(1, kMaxTrials) + ", got " + std::to_string(trials),
        "give the number of data sets per setting in that range (e.g. 200)");
  }
  if (!ThreadCountValid(threads, "SimulateOptions.threads", why)) return false;
  if (covariance_samples < 2 || covariance_samples > kMaxCovarianceSamples) {
    return Invalid(why, "SimulateOptions.covariance_samples",
                   "must be a whole number from " + Range(2, kMaxCovarianceSamples) + ", got " +
                       std::to_string(covariance_samples),
                   "give the number of Monte Carlo samples in that range (e.g. 1000)");
  }
  const std::int64_t settings =
      static_cast<std::int64_t>(setups.size()) * static_cast<std::int64_t>(noise_on.size()) *
      static_cast<std::int64_t>(noise.size()) * static_cast<std::int64_t>(sigmas.size()) *
      static_cast<std::int64_t>(stations.size()) * static_cast<std::int64_t>(outliers.size()) *
      static_cast<std::int64_t>(robot_scales.size());
  if (settings > kMaxSettings) {
    return Invalid(why, "SimulateOptions.stations",
                   "the sweeps make " + std::to_string(settings) + " settings, more than " +
                       std::to_string(kMaxSettings),
                   "sweep fewer setups, noise kinds and devices, noise levels, station counts, "
                   "outlier counts or robot scales");
  }
  const std::int64_t rows = settings * trials * static_cast<std::int64_t>(methods.size());
  if (rows > kMaxTrialRows) {
    return Invalid(why, "SimulateOptions.trials",
                   std::to_string(settings) + " settings x " + std::to_string(trials) +
                       " trials x " + std::to_string(methods.size()) + " methods make " +
                       std::to_string(rows) + " trial rows, more than " +
                       std::to_string(kMaxTrialRows),
                   "give fewer trials, methods or swept values");
  }
  return true;
}

study::StudyOptions MakeStudyOptions(const SimulateOptions& options) {
  study::StudyOptions study;
  study.methods = options.methods;
  study.trials = options.trials;
  study.threads = options.threads;
  study.seed = options.seed;
  study.covariance.method = options.covariance;
  study.covariance.samples = options.covariance_samples;
  study.covariance.seed = options.seed;
  study.reject_outliers = options.reject_outliers;
  study.estimate_noise = options.estimate_noise;
  for (double robot_scale : options.robot_scales) {
    for (handeye::Setup setup : options.setups) {
      for (study::NoiseOn on : options.noise_on) {
        for (sim::NoiseModel::Kind kind : options.noise) {
          for (const study::NoiseLevel& sigma : options.sigmas) {
            for (int n : options.stations) {
              for (int k : options.outliers) {
                study::Setting setting;
                setting.setup = setup;
                setting.stations = n;
                setting.noise_on = on;
                setting.noise_kind = kind;
                setting.translation_sigma = sigma.mm * 1e-3;
                setting.rotation_sigma = sigma.deg / kDegreesPerRadian;
                setting.gross_outliers = k;
                setting.robot_scale = robot_scale;
                study.settings.push_back(setting);
              }
            }
          }
        }
      }
    }
  }
  return study;
}

study::StudyResult Simulate(const SimulateOptions& options) {
  RequireValid(options);
  return study::RunStudy(MakeStudyOptions(options));
}

}  // namespace hecal::jobs
