// The oracle covariance of a study cell: see oracle_covariance.h.
#include "hecal/study/oracle_covariance.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <random>
#include <string>

#include "hecal/core/random_draws.h"
#include "hecal/core/split_mix.h"
#include "hecal/estimation/calibrate.h"
#include "hecal/geometry/se3.h"
#include "hecal/uncertainty/consistency.h"
#include "hecal/uncertainty/parallel_for.h"

namespace hecal::study {
namespace {

// The error and reported covariance of one solve; nullopt when it fails.
struct Solved {
  Vector6d error;
  Matrix6d covariance;
};

std::optional<Solved> SolveOnce(const sim::SimulatedData& data,
                                const estimation::CalibrateOptions& options) {
  try {
    const estimation::CalibrationResult result =
        estimation::Calibrate(data.MeasuredProblem(), options);
    if (!result.X.matrix().allFinite() || !result.covariance) return std::nullopt;
    return Solved{se3::Log(result.X.inverse() * data.X), result.covariance->X()};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// C*, the ratios and the NEES of `trial` from its own error and covariance and the redraws'
// errors; ok stays false when C or C* is not positive definite.
void FillOracle(const Solved& own, const std::vector<Vector6d>& redraws, OracleTrial* trial) {
  const double m = static_cast<double>(redraws.size());
  Matrix6d second = Matrix6d::Zero();
  for (const Vector6d& e : redraws) second += e * e.transpose();
  trial->error = own.error;
  trial->reported = own.covariance;
  trial->oracle = second / m;
  const Eigen::LLT<Matrix6d> oracle(trial->oracle);
  const Eigen::LLT<Matrix6d> sum(second);
  if (oracle.info() != Eigen::Success || sum.info() != Eigen::Success) return;
  trial->nees_reported = uncertainty::Nees(own.error, own.covariance);
  if (!std::isfinite(trial->nees_reported)) return;
  trial->nees_oracle = own.error.dot(oracle.solve(own.error));
  trial->det_ratio = std::pow(own.covariance.determinant() / trial->oracle.determinant(), 1.0 / 6);
  trial->rotation_trace_ratio =
      own.covariance.topLeftCorner<3, 3>().trace() / trial->oracle.topLeftCorner<3, 3>().trace();
  trial->translation_trace_ratio = own.covariance.bottomRightCorner<3, 3>().trace() /
                                   trial->oracle.bottomRightCorner<3, 3>().trace();
  for (const Vector6d& e : redraws) {
    const double h = e.dot(sum.solve(e));  // e_jᵀ (M C*)⁻¹ e_j, below 1
    trial->redraw_nees_oracle.push_back(m * h);
    trial->redraw_nees_oracle_loo.push_back((m - 1.0) * h / (1.0 - h));
  }
  trial->ok = true;
}

double Fraction(const std::vector<double>& values, double limit) {
  if (values.empty()) return 0.0;
  const auto inside =
      std::count_if(values.begin(), values.end(), [limit](double value) { return value <= limit; });
  return static_cast<double>(inside) / static_cast<double>(values.size());
}

double Mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (double value : values) sum += value;
  return values.empty() ? 0.0 : sum / static_cast<double>(values.size());
}

double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle),
                   values.end());
  const double upper = values[middle];
  if (values.size() % 2 == 1) return upper;
  return 0.5 * (upper + *std::max_element(values.begin(),
                                          values.begin() + static_cast<std::ptrdiff_t>(middle)));
}

}  // namespace

OracleSummary SummarizeOracle(const std::vector<OracleTrial>& trials) {
  const double one = uncertainty::ChiSquareQuantile(uncertainty::SigmaProbability(1.0), 6.0);
  const double two = uncertainty::ChiSquareQuantile(uncertainty::SigmaProbability(2.0), 6.0);
  std::vector<double> reported, oracle, pooled_reported, pooled_oracle, pooled_loo;
  std::vector<double> det, rotation, translation;
  for (const OracleTrial& trial : trials) {
    if (!trial.ok) continue;
    reported.push_back(trial.nees_reported);
    oracle.push_back(trial.nees_oracle);
    pooled_reported.insert(pooled_reported.end(), trial.redraw_nees_reported.begin(),
                           trial.redraw_nees_reported.end());
    pooled_oracle.insert(pooled_oracle.end(), trial.redraw_nees_oracle.begin(),
                         trial.redraw_nees_oracle.end());
    pooled_loo.insert(pooled_loo.end(), trial.redraw_nees_oracle_loo.begin(),
                      trial.redraw_nees_oracle_loo.end());
    det.push_back(trial.det_ratio);
    rotation.push_back(trial.rotation_trace_ratio);
    translation.push_back(trial.translation_trace_ratio);
  }
  OracleSummary summary;
  summary.trials = static_cast<int>(reported.size());
  summary.redraws = static_cast<int>(pooled_oracle.size());
  summary.mean_nees_reported = Mean(reported);
  summary.coverage_1sigma_reported = Fraction(reported, one);
  summary.coverage_2sigma_reported = Fraction(reported, two);
  summary.mean_nees_oracle = Mean(oracle);
  summary.coverage_1sigma_oracle = Fraction(oracle, one);
  summary.coverage_2sigma_oracle = Fraction(oracle, two);
  summary.pooled_mean_nees_reported = Mean(pooled_reported);
  summary.pooled_1sigma_reported = Fraction(pooled_reported, one);
  summary.pooled_2sigma_reported = Fraction(pooled_reported, two);
  summary.pooled_1sigma_oracle = Fraction(pooled_oracle, one);
  summary.pooled_2sigma_oracle = Fraction(pooled_oracle, two);
  summary.pooled_1sigma_loo = Fraction(pooled_loo, one);
  summary.pooled_2sigma_loo = Fraction(pooled_loo, two);
  if (!pooled_loo.empty()) {
    // s C* covers NEES / s ≤ q, i.e. NEES ≤ s q: s is the 68.27% quantile of the NEES over q.
    std::vector<double> sorted = pooled_loo;
    std::sort(sorted.begin(), sorted.end());
    const size_t index = static_cast<size_t>(
        std::ceil(uncertainty::SigmaProbability(1.0) * static_cast<double>(sorted.size())) - 1);
    summary.scale_for_1sigma = sorted[std::min(index, sorted.size() - 1)] / one;
    summary.pooled_2sigma_loo_scaled = Fraction(pooled_loo, summary.scale_for_1sigma * two);
  }
  summary.median_det_ratio = Median(det);
  summary.median_rotation_trace_ratio = Median(rotation);
  summary.median_translation_trace_ratio = Median(translation);
  summary.det_ratio_above_1 = det.empty() ? 0.0 : 1.0 - Fraction(det, 1.0);
  return summary;
}

std::vector<OracleTrial> OracleCovariance(const OracleOptions& options) {
  StudyOptions study = options.study;
  study.settings = {options.setting};
  study.methods = {options.method};
  study.trials = options.trials;
  ValidateStudyOptions(study);
  if (options.redraws < 8) {
    throw InputError("OracleOptions.redraws", 0,
                     "needs at least 8 redraws, got " + std::to_string(options.redraws),
                     "a 6 x 6 second moment needs more than 6; e.g. 100");
  }
  const estimation::CalibrateOptions calibrate =
      TrialCalibrateOptions(options.method, options.setting, study);
  const sim::NoiseModel robot = RobotNoise(options.setting);
  const sim::NoiseModel camera = CameraNoise(options.setting);
  std::vector<OracleTrial> trials(static_cast<size_t>(options.trials));
  uncertainty::ParallelFor(options.trials, options.threads, [&](int k) {
    OracleTrial& trial = trials[static_cast<size_t>(k)];
    trial.trial = options.first_trial + k;
    const std::uint64_t seed =
        TrialSeed(study.seed, options.setting.setup, options.setting.stations, trial.trial);
    std::mt19937_64 rng(seed);
    sim::SimulatedData data = SimulateTrial(options.setting, rng);
    const std::optional<Solved> own = SolveOnce(data, calibrate);
    if (!own) return;
    std::vector<Vector6d> errors;
    for (int j = 0; j < options.redraws; ++j) {
      std::mt19937_64 redraw(SplitMix64(seed ^ SplitMix64(static_cast<std::uint64_t>(j) + 1)));
      sim::AddMeasurementNoise(robot, camera, redraw, &data);
      const std::optional<Solved> solved = SolveOnce(data, calibrate);
      if (!solved) continue;
      errors.push_back(solved->error);
      trial.redraw_nees_reported.push_back(uncertainty::Nees(solved->error, solved->covariance));
    }
    trial.redraws = static_cast<int>(errors.size());
    if (trial.redraws >= 8) FillOracle(*own, errors, &trial);
  });
  return trials;
}

std::vector<OracleTrial> OracleGaussianReference(int trials, int redraws, std::uint64_t seed) {
  std::vector<OracleTrial> result(static_cast<size_t>(trials));
  std::mt19937_64 rng(seed);
  hecal::NormalDistribution normal;
  const auto draw = [&] {
    Vector6d e;
    for (int i = 0; i < 6; ++i) e[i] = normal(rng);
    return e;
  };
  for (int k = 0; k < trials; ++k) {
    OracleTrial& trial = result[static_cast<size_t>(k)];
    trial.trial = k;
    const Solved own{draw(), Matrix6d::Identity()};
    std::vector<Vector6d> errors;
    for (int j = 0; j < redraws; ++j) {
      errors.push_back(draw());
      trial.redraw_nees_reported.push_back(errors.back().squaredNorm());
    }
    trial.redraws = redraws;
    FillOracle(own, errors, &trial);
  }
  return result;
}

}  // namespace hecal::study
