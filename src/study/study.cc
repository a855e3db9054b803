#include "hecal/study/study.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <random>
#include <stdexcept>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/core/split_mix.h"
#include "hecal/estimation/bound.h"
#include "hecal/estimation/calibrate.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"
#include "hecal/handeye/station_consensus.h"
#include "hecal/sim/gross_outliers.h"
#include "hecal/sim/thesis_protocol.h"
#include "hecal/sim/triangle_threshold.h"
#include "hecal/uncertainty/parallel_for.h"

namespace hecal::study {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Errors below these are rounding noise, never outliers (sim/triangle_threshold.h).
constexpr double kOutlierFloorRotation = 1e-9;     // radians
constexpr double kOutlierFloorTranslation = 1e-9;  // metres

// RMS magnitude per component of the noise a model puts on a pose.
// For the robot (`robot`) or the camera: kPnp shapes the camera's noise only (study.h).
estimation::PoseSigma ModelSigma(const Setting& setting, bool robot) {
  const double scale = robot ? setting.robot_scale : 1.0;
  const sim::NoiseModel::Kind kind = robot && setting.noise_kind == sim::NoiseModel::Kind::kPnp
                                         ? sim::NoiseModel::Kind::kGaussian
                                         : setting.noise_kind;
  switch (kind) {
    case sim::NoiseModel::Kind::kUniform:
      return {scale * setting.rotation_sigma / std::sqrt(3.0),
              scale * setting.translation_sigma / std::sqrt(3.0)};
    case sim::NoiseModel::Kind::kPnp:
      return {std::sqrt((4.0 + 4.0 + 0.01) / 3.0) * setting.rotation_sigma,
              std::sqrt((0.25 + 0.25 + 25.0) / 3.0) * setting.translation_sigma};
    default:
      return {scale * setting.rotation_sigma, scale * setting.translation_sigma};
  }
}

sim::NoiseModel NoiseFor(const Setting& setting, bool robot, bool noisy) {
  sim::NoiseModel model;
  model.kind = setting.noise_kind;
  if (robot && model.kind == sim::NoiseModel::Kind::kPnp)
    model.kind = sim::NoiseModel::Kind::kGaussian;
  if (noisy) {
    const double scale = robot ? setting.robot_scale : 1.0;
    model.rotation_sigma = scale * setting.rotation_sigma;
    model.translation_sigma = scale * setting.translation_sigma;
  }
  return model;
}

bool IsFinite(const Pose& T) {
  return T.matrix().allFinite();
}

// The noise model the refinements are told (study.h, next to RobotSigma).
void SetRefinementSigmas(const Setting& setting, estimation::CalibrateOptions* options) {
  const estimation::PoseSigma robot = RobotSigma(setting);
  const estimation::PoseSigma camera = CameraSigma(setting);
  const double rotation = std::max(robot.rotation, camera.rotation);
  const double translation = std::max(robot.translation, camera.translation);
  if (rotation == 0.0 && translation == 0.0) {
    // Noise-free: the exact fit is the minimiser whatever the weights.
    options->robot_sigma = options->camera_sigma = estimation::PoseSigma{1e-3, 1e-3};
    return;
  }
  if (rotation == 0.0 || translation == 0.0) return;  // estimated from the residuals
  const double floor = 1e-3;
  options->robot_sigma = estimation::PoseSigma{std::max(robot.rotation, floor * rotation),
                                               std::max(robot.translation, floor * translation)};
  options->camera_sigma = estimation::PoseSigma{std::max(camera.rotation, floor * rotation),
                                                std::max(camera.translation, floor * translation)};
}

struct Estimate {
  Pose X;
  std::optional<Matrix6d> covariance_X;
  std::optional<Matrix6d> covariance_X_model;  // before the model check
  bool check_used = false;
  std::vector<int> rejected;          // with outlier rejection: the stations left out
  estimation::PoseSigma robot_sigma;  // given or estimated (Calibrate only)
};

// One method on one data set. Without a covariance, closed-form methods go straight to their
// solver (what `hecal bench` times) and the refinements through Calibrate with the noise model
// of the setting; with one, every method goes through Calibrate with that noise model.
Estimate SolveX(estimation::Method method, const handeye::Problem& problem, const Setting& setting,
                const StudyOptions& study) {
  const bool wants_covariance = study.covariance.method != estimation::CovarianceMethod::kNone;
  const std::optional<handeye::ClosedForm> form = estimation::Info(method).closed_form;
  if (form && !wants_covariance && !study.reject_outliers) {
    return {handeye::SolveClosedForm(*form, problem).X, std::nullopt, std::nullopt, false, {}, {}};
  }
  const estimation::CalibrationResult result =
      estimation::Calibrate(problem, TrialCalibrateOptions(method, setting, study));
  if (!result.covariance) {
    return {result.X, std::nullopt, std::nullopt, false, result.rejected, result.robot_sigma};
  }
  const bool checked = result.model_check && result.model_check->possible;
  return {result.X,
          result.covariance->X(),
          checked ? Matrix6d(result.model_check->model_covariance.topLeftCorner<6, 6>())
                  : result.covariance->X(),
          checked && result.model_check->used,
          result.rejected,
          result.robot_sigma};
}

// The first-order bound of the data set at the truth: 0 without noise, NaN when the noise model
// or the stations make the information singular.
Bound BoundAtTruth(const sim::SimulatedData& data, const Setting& setting) {
  const estimation::PoseSigma robot = RobotSigma(setting);
  const estimation::PoseSigma camera = CameraSigma(setting);
  if (robot.rotation + robot.translation + camera.rotation + camera.translation == 0.0) {
    return {0.0, 0.0};
  }
  const handeye::Problem truth =
      handeye::MakeProblem(data.setup, data.T_base_gripper_true, data.T_camera_target_true);
  try {
    const estimation::AccuracyBound bound =
        estimation::FirstOrderBound(truth, data.X, data.Z, robot, camera);
    return {bound.rotation_rmse_X, bound.translation_rmse_X};
  } catch (const DegenerateError&) {  // singular information
    return {kNaN, kNaN};
  } catch (const std::invalid_argument&) {  // a singular noise model
    return {kNaN, kNaN};
  }
}

struct Job {
  int setting;
  int trial;
};

}  // namespace

std::optional<NoiseOn> ParseNoiseOn(std::string_view text) {
  if (text == "robot") return NoiseOn::kRobot;
  if (text == "camera") return NoiseOn::kCamera;
  if (text == "both") return NoiseOn::kBoth;
  return std::nullopt;
}

std::string_view NoiseOnName(NoiseOn noise_on) {
  switch (noise_on) {
    case NoiseOn::kRobot:
      return "robot";
    case NoiseOn::kCamera:
      return "camera";
    case NoiseOn::kBoth:
      return "both";
  }
  return "both";
}

std::string_view TrialStatusName(TrialStatus status) {
  switch (status) {
    case TrialStatus::kOk:
      return "ok";
    case TrialStatus::kThrew:
      return "threw";
    case TrialStatus::kNonFinite:
      return "non-finite";
  }
  return "ok";
}

estimation::PoseSigma RobotSigma(const Setting& setting) {
  if (setting.noise_on == NoiseOn::kCamera) return {};
  return ModelSigma(setting, true);
}

estimation::PoseSigma CameraSigma(const Setting& setting) {
  if (setting.noise_on == NoiseOn::kRobot) return {};
  return ModelSigma(setting, false);
}

sim::NoiseModel RobotNoise(const Setting& setting) {
  return NoiseFor(setting, true, setting.noise_on != NoiseOn::kCamera);
}

sim::NoiseModel CameraNoise(const Setting& setting) {
  return NoiseFor(setting, false, setting.noise_on != NoiseOn::kRobot);
}

sim::SimulatedData SimulateTrial(const Setting& setting, std::mt19937_64& rng) {
  sim::ProtocolOptions protocol;
  protocol.setup = setting.setup;
  protocol.stations = setting.stations;
  return sim::SimulateThesisProtocol(protocol, RobotNoise(setting), CameraNoise(setting), rng);
}

estimation::CalibrateOptions TrialCalibrateOptions(estimation::Method method,
                                                   const Setting& setting,
                                                   const StudyOptions& study) {
  estimation::CalibrateOptions options;
  options.method = method;
  options.covariance = study.covariance;
  options.covariance.threads = 1;  // the trials run in parallel already
  options.reject_outliers = study.reject_outliers;
  options.model_check = study.covariance.method != estimation::CovarianceMethod::kNone;
  if (!study.estimate_noise) SetRefinementSigmas(setting, &options);
  return options;
}

void ValidateStudyOptions(const StudyOptions& options) {
  if (options.settings.empty()) {
    throw InputError("StudyOptions.settings", 0, "the study has no setting",
                     "give at least one value");
  }
  if (options.methods.empty()) {
    throw InputError("StudyOptions.methods", 0, "no method selected",
                     "name one or more methods, or all");
  }
  if (options.trials < 1) {
    throw InputError("StudyOptions.trials", 0,
                     "needs at least 1 trial, got " + std::to_string(options.trials), "e.g. 200");
  }
  if (options.threads < 0) {
    throw InputError("StudyOptions.threads", 0, "cannot be negative", "0 uses every core");
  }
  RequireValid(options.covariance);
  for (const Setting& s : options.settings) {
    if (s.stations < 3) {
      throw InputError("Setting.stations", 0,
                       "needs at least 3 stations (2 motions), got " + std::to_string(s.stations),
                       "the thesis' k motions are k + 1 stations");
    }
    if (s.gross_outliers < 0 || s.stations - s.gross_outliers < 3) {
      throw InputError("Setting.gross_outliers", 0,
                       std::to_string(s.gross_outliers) + " gross outliers in " +
                           std::to_string(s.stations) + " stations leave fewer than 3 good ones",
                       "give 0 to stations - 3 outliers");
    }
    if (!(s.translation_sigma >= 0.0) || !(s.rotation_sigma >= 0.0) ||
        !std::isfinite(s.translation_sigma) || !std::isfinite(s.rotation_sigma)) {
      throw InputError("Setting.rotation_sigma", 0, "noise levels must be finite and non-negative",
                       "e.g. 0, 0.3 or 1");
    }
  }
}

uint64_t TrialSeed(uint64_t seed, handeye::Setup setup, int stations, int trial) {
  uint64_t h = SplitMix64(seed);
  h = SplitMix64(h ^ (setup == handeye::Setup::kEyeInHand ? 0x11ULL : 0x22ULL));
  h = SplitMix64(h ^ static_cast<uint64_t>(stations));
  return SplitMix64(h ^ static_cast<uint64_t>(trial));
}

RotationTranslation PoseError(const Pose& estimate, const Pose& truth) {
  return {so3::Distance(truth.linear(), estimate.linear()),
          (estimate.translation() - truth.translation()).norm()};
}

StudyResult RunStudy(const StudyOptions& options) {
  ValidateStudyOptions(options);
  StudyResult result;
  result.options = options;
  const int settings = static_cast<int>(options.settings.size());
  const int methods = static_cast<int>(options.methods.size());
  const int trials = options.trials;
  const int jobs = settings * trials;
  result.trials.resize(static_cast<size_t>(jobs) * methods);
  result.bounds.assign(settings, std::vector<Bound>(trials));

  auto run_job = [&](const Job& job) {
    const Setting& setting = options.settings[job.setting];
    std::mt19937_64 rng(TrialSeed(options.seed, setting.setup, setting.stations, job.trial));
    sim::SimulatedData data = SimulateTrial(setting, rng);
    const sim::SimulatedData clean_data = data;
    const std::vector<int> replaced = sim::InjectGrossOutliers(&data, setting.gross_outliers, rng);
    const handeye::Problem problem = data.MeasuredProblem();
    std::vector<bool> good(problem.A.size(), true);
    for (int i : replaced) good[static_cast<size_t>(i)] = false;
    const handeye::Problem clean = handeye::SubProblem(clean_data.MeasuredProblem(), good);
    const size_t base = (static_cast<size_t>(job.setting) * trials + job.trial) * methods;
    for (int m = 0; m < methods; ++m) {
      TrialResult& trial = result.trials[base + m];
      trial.setting = job.setting;
      trial.trial = job.trial;
      trial.method = options.methods[m];
      trial.rotation_error = trial.translation_error = kNaN;
      try {
        const Estimate estimate = SolveX(trial.method, problem, setting, options);
        if (!IsFinite(estimate.X)) {
          trial.status = TrialStatus::kNonFinite;
          continue;
        }
        const RotationTranslation error = PoseError(estimate.X, data.X);
        trial.rotation_error = error.rotation;
        trial.translation_error = error.translation;
        trial.robot_sigma = estimate.robot_sigma;
        if (estimate.covariance_X) {
          trial.error_X = se3::Log(estimate.X.inverse() * data.X);
          trial.covariance_X = estimate.covariance_X;
          trial.nees = uncertainty::Nees(trial.error_X, *estimate.covariance_X);
          trial.covariance_X_model = estimate.covariance_X_model;
          trial.nees_model = uncertainty::Nees(trial.error_X, *estimate.covariance_X_model);
          trial.check_used = estimate.check_used;
        }
        for (int i : estimate.rejected)
          ++(good[static_cast<size_t>(i)] ? trial.rejected_good : trial.rejected_outliers);
        if (!replaced.empty()) {
          const RotationTranslation clean_error =
              PoseError(SolveX(trial.method, clean, setting, options).X, data.X);
          trial.rotation_error_clean = clean_error.rotation;
          trial.translation_error_clean = clean_error.translation;
        }
      } catch (const std::exception& e) {
        trial.status = TrialStatus::kThrew;
        trial.message = e.what();
      }
    }
    result.bounds[job.setting][job.trial] = BoundAtTruth(data, setting);
  };

  uncertainty::ParallelFor(jobs, options.threads, [&](int j) {
    run_job({j / trials, j % trials});
  });

  // Outliers and summaries per (setting, method), in a fixed order.
  for (int s = 0; s < settings; ++s) {
    double rotation_sq = 0.0, translation_sq = 0.0;
    for (const Bound& b : result.bounds[s]) {
      rotation_sq += b.rotation * b.rotation;
      translation_sq += b.translation * b.translation;
    }
    result.setting_bounds.push_back(
        {std::sqrt(rotation_sq / trials), std::sqrt(translation_sq / trials)});
    for (int m = 0; m < methods; ++m) {
      std::vector<double> rotation(trials), translation(trials);
      for (int t = 0; t < trials; ++t) {
        const TrialResult& trial =
            result.trials[(static_cast<size_t>(s) * trials + t) * methods + m];
        rotation[t] = trial.rotation_error;
        translation[t] = trial.translation_error;
      }
      sim::TriangleThresholdOptions rotation_options, translation_options;
      rotation_options.floor = kOutlierFloorRotation;
      translation_options.floor = kOutlierFloorTranslation;
      const sim::TriangleThresholdResult rotation_outliers =
          sim::TriangleThreshold(rotation, rotation_options);
      const sim::TriangleThresholdResult translation_outliers =
          sim::TriangleThreshold(translation, translation_options);
      MethodSummary summary;
      summary.setting = s;
      summary.method = options.methods[m];
      summary.trials = trials;
      summary.rotation = sim::Summarize(rotation);
      summary.translation = sim::Summarize(translation);
      summary.failures = summary.rotation.failures;
      double inlier_rotation_sq = 0.0, inlier_translation_sq = 0.0;
      int inliers = 0;
      double worst_rotation = 0.0, worst_translation = 0.0;
      double clean_rotation_sq = 0.0, clean_translation_sq = 0.0;
      int clean_trials = 0;
      const Setting& setting = options.settings[s];
      std::vector<Eigen::VectorXd> errors;
      std::vector<Eigen::MatrixXd> covariances, model_covariances;
      for (int t = 0; t < trials; ++t) {
        TrialResult& trial = result.trials[(static_cast<size_t>(s) * trials + t) * methods + m];
        if (trial.status != TrialStatus::kOk) continue;
        trial.outlier = rotation_outliers.outlier[t] || translation_outliers.outlier[t];
        if (trial.outlier) {
          ++summary.outliers;
        } else {
          ++inliers;
          inlier_rotation_sq += rotation[t] * rotation[t];
          inlier_translation_sq += translation[t] * translation[t];
        }
        if (trial.covariance_X) {
          errors.emplace_back(trial.error_X);
          covariances.emplace_back(*trial.covariance_X);
          model_covariances.emplace_back(*trial.covariance_X_model);
          summary.check_used += trial.check_used ? 1 : 0;
        }
        summary.outliers_injected += setting.gross_outliers;
        summary.outliers_rejected += trial.rejected_outliers;
        summary.good_stations += setting.stations - setting.gross_outliers;
        summary.good_rejected += trial.rejected_good;
        if (trial.rejected_outliers == setting.gross_outliers) ++summary.trials_all_found;
        if (std::isfinite(trial.rotation_error_clean)) {
          ++clean_trials;
          clean_rotation_sq += trial.rotation_error_clean * trial.rotation_error_clean;
          clean_translation_sq += trial.translation_error_clean * trial.translation_error_clean;
        }
        const Bound& bound = result.bounds[s][t];
        worst_rotation = std::max(worst_rotation, rotation[t] / bound.rotation);
        worst_translation = std::max(worst_translation, translation[t] / bound.translation);
      }
      summary.rotation_rmse_inliers = inliers > 0 ? std::sqrt(inlier_rotation_sq / inliers) : kNaN;
      summary.translation_rmse_inliers =
          inliers > 0 ? std::sqrt(inlier_translation_sq / inliers) : kNaN;
      if (clean_trials > 0) {
        summary.rotation_rmse_clean = std::sqrt(clean_rotation_sq / clean_trials);
        summary.translation_rmse_clean = std::sqrt(clean_translation_sq / clean_trials);
      }
      const bool bounded = std::isfinite(result.setting_bounds[s].rotation) &&
                           result.setting_bounds[s].rotation > 0.0;
      summary.worst_rotation_over_bound = bounded ? worst_rotation : kNaN;
      summary.worst_translation_over_bound = bounded ? worst_translation : kNaN;
      if (!errors.empty()) {
        summary.consistency = uncertainty::AssessConsistency(errors, covariances);
        summary.consistency_model = uncertainty::AssessConsistency(errors, model_covariances);
      }
      result.summaries.push_back(summary);
    }
  }
  return result;
}

std::vector<estimation::Method> EveryMethod() {
  std::vector<estimation::Method> methods;
  for (const estimation::MethodInfo& info : estimation::AllMethods())
    methods.push_back(info.method);
  return methods;
}

}  // namespace hecal::study
