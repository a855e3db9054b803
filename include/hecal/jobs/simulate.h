// The job of `hecal simulate`: the thesis study (docs/thesis-study.md, study.h) over the
// Cartesian product of sweeps, from typed options. Every list is a sweep; the settings are
// robot_scales × setups × noise_on × noise × sigmas × stations × outliers, in that nesting
// order (the last varies fastest), each run with the same trials, methods, seed and covariance.
//
// Units: a noise level is given as the user reads it — millimetres and degrees per component
// (the thesis' "n mm / n°"); the study works in metres and radians (Setting). For uniform noise
// the level is the half-width, for systematic noise the constant offset per component.
//
// Bounds (IsValid; every number that reaches an allocation or a loop is checked before any
// work): stations 3 … 100000 (the thesis' k motions are k + 1 stations), outliers 0 … 100000,
// trials 1 … 100000, threads 0 … 256 (0 = every core), covariance samples 2 … 100000, noise
// levels 0 … 1000 mm and 0 … 180 deg per axis, robot scale above 0 and at most 1000 with the
// robot noise (level × scale) within the same 1000 mm / 180 deg, at most 10000 settings and
// 10^6 trial rows (settings × trials × methods). A bad value names the field
// ("SimulateOptions.stations", core/options_check.h); Simulate throws it as hecal::InputError.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/covariance_method.h"
#include "hecal/estimation/methods.h"
#include "hecal/handeye/problem.h"
#include "hecal/sim/noise.h"
#include "hecal/study/study.h"

namespace hecal::jobs {

// Every method, in estimation::AllMethods() order (`--method all`).
struct SimulateOptions {
  static constexpr int kMinStations = 3;
  static constexpr int kMaxStations = 100000;
  static constexpr int kMaxTrials = 100000;
  static constexpr int kMaxThreads = 256;
  static constexpr int kMaxCovarianceSamples = 100000;
  static constexpr double kMaxSigmaMm = study::kMaxSigmaMm;
  static constexpr double kMaxSigmaDeg = study::kMaxSigmaDeg;
  static constexpr double kMaxRobotScale = 1000.0;
  static constexpr std::int64_t kMaxSettings = 10000;
  static constexpr std::int64_t kMaxTrialRows = 1000000;

  std::vector<handeye::Setup> setups = {handeye::Setup::kEyeInHand};
  std::vector<int> stations = {3, 5, 10, 15, 20};
  std::vector<study::NoiseOn> noise_on = {study::NoiseOn::kBoth};
  std::vector<sim::NoiseModel::Kind> noise = {sim::NoiseModel::Kind::kGaussian};
  std::vector<study::NoiseLevel> sigmas = {{0.0, 0.0}, {0.3, 0.3}, {1.0, 1.0}};
  std::vector<int> outliers = {0};         // gross outliers per data set (sim/gross_outliers.h)
  std::vector<double> robot_scales = {1};  // robot noise = scale × level, camera noise = level
  std::vector<estimation::Method> methods = study::EveryMethod();
  int trials = 200;
  std::uint64_t seed = 1;
  int threads = 0;  // 0: every core
  // The covariance each trial predicts for X: kNone (default) = none; nullopt = each method's
  // own default (estimation::DefaultCovarianceMethod).
  std::optional<estimation::CovarianceMethod> covariance = estimation::CovarianceMethod::kNone;
  int covariance_samples = 1000;  // Monte Carlo samples per trial
  bool reject_outliers = false;   // study::StudyOptions::reject_outliers
  bool estimate_noise = false;    // study::StudyOptions::estimate_noise

  // True when every field is in its range (above); else false with "SimulateOptions.<field>:
  // problem (fix: …)" in `*why`.
  bool IsValid(std::string* why) const;
};

// The study options of the sweep: one Setting per combination, in the order above.
study::StudyOptions MakeStudyOptions(const SimulateOptions& options);

// Runs the study (study::RunStudy); throws hecal::InputError when !options.IsValid.
study::StudyResult Simulate(const SimulateOptions& options);

}  // namespace hecal::jobs
