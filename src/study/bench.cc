// The benchmark protocol: see bench.h.
#include "hecal/study/bench.h"

#include <cmath>
#include <ctime>
#include <exception>
#include <memory>
#include <random>

#include "hecal/core/options_check.h"
#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/calibration_covariance.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/study/study_csv.h"

namespace hecal::study {
namespace {
constexpr double kFailureDeg = 10.0;

// Every timed solve writes here, so the optimiser cannot drop it.
volatile double g_sink = 0.0;

// CPU time of the whole process (every thread): unlike wall time it does not count other
// programs sharing the cores, and it still counts any worker threads a library starts.
double ProcessCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

sim::NoiseModel Noise(const NoiseLevel& sigma) {
  return {sim::NoiseModel::Kind::kGaussian, sigma.deg / kDegreesPerRadian, sigma.mm * 1e-3};
}

// The solve only (no covariance, no model check), told the true sigmas unless the level is 0.
estimation::CalibrateOptions SolveOnly(const NoiseLevel& sigma) {
  estimation::CalibrateOptions options;
  options.covariance.method = estimation::CovarianceMethod::kNone;
  options.model_check = false;
  // The solve alone: the described size, the target's scale not estimated (target_scale.h).
  options.target_scale = estimation::TargetScaleMode::kGiven;
  options.given_target_scale = 1.0;
  const sim::NoiseModel noise = Noise(sigma);
  if (!noise.IsZero()) {
    options.robot_sigma = estimation::PoseSigma{noise.rotation_sigma, noise.translation_sigma};
    options.camera_sigma = options.robot_sigma;
  }
  return options;
}

// Whole passes over the sets until `min_time` seconds of process CPU time are spent.
double MicrosecondsPerSolve(std::size_t sets, const BenchSolver& solve, double min_time) {
  const double begin = ProcessCpuSeconds();
  long solves = 0;
  double elapsed = 0.0;
  do {
    for (std::size_t i = 0; i < sets; ++i) {
      try {
        g_sink = solve(i).translation()(0);
      } catch (const std::exception&) {
        g_sink = 0.0;
      }
      ++solves;
    }
    elapsed = ProcessCpuSeconds() - begin;
  } while (elapsed < min_time);
  return elapsed * 1e6 / static_cast<double>(solves);
}

BenchRow Measure(const std::string& impl, estimation::Method method, BenchStart start, int stations,
                 const std::vector<BenchDataSet>& sets, const BenchSolver& solve, double min_time) {
  BenchRow row;
  row.impl = impl;
  row.method = method;
  row.start = start;
  row.stations = stations;
  row.datasets = static_cast<int>(sets.size());
  row.accuracy = MeasureAccuracy(sets, solve);
  row.us_per_solve = MicrosecondsPerSolve(sets.size(), solve, min_time);
  return row;
}

}  // namespace

bool BenchOptions::IsValid(std::string* why) const {
  if (stations.empty()) {
    return Invalid(why, "BenchOptions.stations", "no station count", "give at least one, e.g. 10");
  }
  for (int n : stations) {
    if (n < 3 || n > kMaxStations) {
      std::string problem = "'";
      problem += std::to_string(n);
      problem += "' is outside the range 3 to ";
      problem += std::to_string(kMaxStations);
      return Invalid(why, "BenchOptions.stations", problem, "e.g. 10,20,50");
    }
  }
  if (methods.empty()) {
    return Invalid(why, "BenchOptions.methods", "no method selected",
                   "name one or more methods, or all");
  }
  if (datasets < 1 || datasets > kMaxDatasets) {
    return Invalid(why, "BenchOptions.datasets",
                   "must be a whole number from 1 to " + std::to_string(kMaxDatasets) + ", got " +
                       std::to_string(datasets),
                   "give the number of data sets per station count in that range (e.g. 10)");
  }
  for (int n : stations) {
    if (std::int64_t{n} * datasets > kMaxPoses) {
      return Invalid(why, "BenchOptions.datasets",
                     std::to_string(n) + " stations x " + std::to_string(datasets) +
                         " data sets is more than " + std::to_string(kMaxPoses) +
                         " poses, the most hecal bench generates",
                     "give fewer data sets or fewer stations");
    }
  }
  if (!(min_time >= 0.0 && min_time <= kMaxMinTime)) {
    return Invalid(
        why, "BenchOptions.min_time",
        "must be 0 to " + FormatNumber(kMaxMinTime) + " seconds, got " + FormatNumber(min_time),
        "e.g. 0.2");
  }
  if (!(sigma.mm >= 0.0 && sigma.mm <= kMaxSigmaMm) ||
      !(sigma.deg >= 0.0 && sigma.deg <= kMaxSigmaDeg)) {
    return Invalid(why, "BenchOptions.sigma",
                   "noise levels must be 0 to " + FormatNumber(kMaxSigmaMm) + " mm and 0 to " +
                       FormatNumber(kMaxSigmaDeg) + " deg per axis, got " + FormatNumber(sigma.mm) +
                       " mm / " + FormatNumber(sigma.deg) + " deg",
                   "give the standard deviation of one axis in mm and degrees, e.g. 0.5/0.1");
  }
  return true;
}

std::vector<BenchDataSet> MakeBenchDataSets(handeye::Setup setup, int stations, int datasets,
                                            const NoiseLevel& sigma, std::uint64_t seed) {
  const sim::NoiseModel noise = Noise(sigma);
  std::vector<BenchDataSet> sets;
  for (int d = 0; d < datasets; ++d) {
    std::mt19937_64 rng(TrialSeed(seed, setup, stations, d));
    sim::ProtocolOptions protocol;
    protocol.setup = setup;
    protocol.stations = stations;
    BenchDataSet set;
    set.data = sim::SimulateThesisProtocol(protocol, noise, noise, rng);
    set.problem = set.data.MeasuredProblem();
    sets.push_back(std::move(set));
  }
  return sets;
}

BenchSolver HecalSolver(estimation::Method method, const std::vector<BenchDataSet>& sets,
                        const NoiseLevel& sigma) {
  if (const std::optional<handeye::ClosedForm> form = estimation::Info(method).closed_form) {
    return [form = *form, &sets](std::size_t i) {
      return handeye::SolveClosedForm(form, sets[i].problem).X;
    };
  }
  estimation::CalibrateOptions options = SolveOnly(sigma);
  options.method = method;
  return
      [options, &sets](std::size_t i) { return estimation::Calibrate(sets[i].problem, options).X; };
}

BenchSolver GoodStartMlSolver(const std::vector<BenchDataSet>& sets, const NoiseLevel& sigma) {
  const estimation::CalibrateOptions options = SolveOnly(sigma);
  auto starts = std::make_shared<std::vector<estimation::CalibrationResult>>();
  for (const BenchDataSet& set : sets) {
    estimation::CalibrationResult start;  // a set ml cannot calibrate: Resolve fails there too
    start.robot_sigma = options.robot_sigma.value_or(estimation::PoseSigma{});
    start.camera_sigma = start.robot_sigma;
    try {
      start = estimation::Calibrate(set.problem, options);
    } catch (const std::exception&) {
    }
    start.X = set.data.X;
    start.Z = set.data.Z;
    starts->push_back(std::move(start));
  }
  return [starts, options, &sets](std::size_t i) {
    return estimation::Resolve(sets[i].problem, (*starts)[i], options).X;
  };
}

BenchAccuracy MeasureAccuracy(const std::vector<BenchDataSet>& sets, const BenchSolver& solve) {
  BenchAccuracy accuracy;
  double rotation_sq = 0.0, translation_sq = 0.0;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    try {
      const Pose X = solve(i);
      if (!X.matrix().allFinite()) {
        ++accuracy.failures;
        continue;
      }
      const RotationTranslation error = PoseError(X, sets[i].data.X);
      rotation_sq += error.rotation * error.rotation;
      translation_sq += error.translation * error.translation;
      accuracy.worst_rotation = std::max(accuracy.worst_rotation, error.rotation);
      accuracy.worst_translation = std::max(accuracy.worst_translation, error.translation);
      ++accuracy.finite;
      if (error.rotation * kDegreesPerRadian > kFailureDeg) ++accuracy.failures;
    } catch (const std::exception&) {
      ++accuracy.failures;
    }
  }
  if (accuracy.finite > 0) {
    accuracy.rotation_error = std::sqrt(rotation_sq / accuracy.finite);
    accuracy.translation_error = std::sqrt(translation_sq / accuracy.finite);
  }
  return accuracy;
}

BenchResult RunBench(const BenchOptions& options, const std::optional<BenchPeer>& peer) {
  RequireValid(options);
  BenchResult result;
  result.options = options;
  for (int n : options.stations) {
    const std::vector<BenchDataSet> sets =
        MakeBenchDataSets(options.setup, n, options.datasets, options.sigma, options.seed);
    for (estimation::Method method : options.methods) {
      const BenchStart start = estimation::Info(method).closed_form ? BenchStart::kNotApplicable
                                                                    : BenchStart::kClosedForm;
      result.rows.push_back(Measure("hecal", method, start, n, sets,
                                    HecalSolver(method, sets, options.sigma), options.min_time));
      if (method == estimation::Method::kMl) {
        result.rows.push_back(Measure("hecal", method, BenchStart::kGood, n, sets,
                                      GoodStartMlSolver(sets, options.sigma), options.min_time));
      }
      if (!peer) continue;
      if (const std::optional<BenchSolver> solve = peer->prepare(method, sets)) {
        result.rows.push_back(Measure(peer->name, method, BenchStart::kNotApplicable, n, sets,
                                      *solve, options.min_time));
      }
    }
  }
  return result;
}

}  // namespace hecal::study
