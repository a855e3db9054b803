// The thesis study (docs/thesis-study.md), extended to every hecal method side by side: Monte-Carlo
// trials on the thesis protocol (sim/thesis_protocol.h) for a list of settings (setup, number
// of stations, which device is noisy, noise kind, noise level), every requested method solving
// the IDENTICAL data set in each trial, errors against the truth, triangle-threshold outliers
// (sim/triangle_threshold.h) and summaries (sim/summary_statistics.h), plus the first-order
// (Cramér–Rao-type) bound of the `ml` estimate at the truth for comparison.
//
// Errors of an estimate X̂ against the truth X̃ (thesis §5.1): rotation = angle of R̃⁻¹ R̂
// (radians here, degrees in files), translation = |t̂ − t̃| (metres here, mm in files). Only X,
// the hand–eye transform, is scored (as in the thesis).
//
// Reproducibility: trial k of a setting draws its data from a std::mt19937_64 seeded with a
// SplitMix64 hash of (seed, setup, stations, k), so
//  - the same seed gives the same results whatever the number of threads (each trial is one job;
//    results go to fixed slots);
//  - settings that differ only in the noise share the same ground truth and station poses per
//    trial (common random numbers: noise sweeps compare like with like).
// Covariance (optional): with StudyOptions::covariance other than kNone every method
// goes through estimation::Calibrate with the setting's noise model (the sigmas below, for
// the closed-form methods too) and that covariance method, and each trial records the error of
// X in the tangent space, e = Log(X̂⁻¹ X̃) (right perturbation, (ω, v)), with its predicted
// covariance; the summary adds their consistency (uncertainty/consistency.h: mean NEES and its
// 95% χ² band for 6 dof, 1σ/2σ ellipsoid coverage, predicted/empirical sd per axis). Inner
// solves run on the trial's own thread (the trials are already parallel).
// With the model check (estimation/model_check.h, on in Calibrate) the reported covariance may be
// inflated; the model's own covariance is recorded beside it, with its own consistency.
// Gross outliers (Setting::gross_outliers, sim/gross_outliers.h): after the noise, k stations'
// robot poses are replaced by random poses (drawn from the same trial stream, so settings that
// differ only in k share their truth, stations and noise); each method also solves the same data
// set without those stations, the reference its error is compared with. With
// StudyOptions::reject_outliers the study counts which stations each method rejected.
// Failures: a method that throws (e.g. DegenerateError) or returns a non-finite pose is a failed
// trial (status and message kept, errors NaN); failures are not outliers and are left out of
// the statistics.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/estimation/calibrate.h"
#include "hecal/estimation/covariance_method.h"
#include "hecal/estimation/methods.h"
#include "hecal/estimation/pose_sigma.h"
#include "hecal/handeye/problem.h"
#include "hecal/sim/noise.h"
#include "hecal/sim/summary_statistics.h"
#include "hecal/sim/thesis_protocol.h"
#include "hecal/uncertainty/consistency.h"

namespace hecal::study {

// Every method of estimation::AllMethods(), in its order: what a study runs by default.
std::vector<estimation::Method> EveryMethod();

// The largest noise level a study simulates, per axis.
inline constexpr double kMaxSigmaMm = 1000.0;
inline constexpr double kMaxSigmaDeg = 180.0;

// Which measurements carry the noise.
enum class NoiseOn { kRobot, kCamera, kBoth };
// "robot" | "camera" | "both"; nullopt otherwise.
std::optional<NoiseOn> ParseNoiseOn(std::string_view text);
std::string_view NoiseOnName(NoiseOn noise_on);

// A noise level as the user reads it (the thesis' "n mm / n°"): millimetres on each translation
// component, degrees on each rotation component.
struct NoiseLevel {
  double mm = 0.0;
  double deg = 0.0;
};

// One cell of the sweep.
struct Setting {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  int stations = 15;
  NoiseOn noise_on = NoiseOn::kBoth;
  sim::NoiseModel::Kind noise_kind = sim::NoiseModel::Kind::kGaussian;
  double translation_sigma = 0.0;  // metres, per component
  double rotation_sigma = 0.0;     // radians, per component
  // Stations per data set whose robot pose is replaced by a random pose (sim/gross_outliers.h).
  int gross_outliers = 0;
  // The robot's noise is robot_scale times the setting's level (the camera's is the level):
  // 5 makes the robot five times noisier than the camera, a split the estimated model (equal
  // split) gets wrong.
  double robot_scale = 1.0;
};

// Per-component standard deviation of the noise a setting puts on one pose (zero for the
// noise-free device): σ for Gaussian, σ/√3 for uniform on [−σ, σ], and σ for systematic (the
// offset's magnitude; it is not random). This is what the bound uses.
// The refinements (ml, strobl) are told these sigmas, except that
//  - a device without noise gets 1e-3 of the other's sigma (a singular noise model has no
//    whitening; the limit is the same estimator);
//  - noise-free data get a nominal 1 mm / 1 mrad (the exact fit minimises any weighting);
//  - when the level has a zero rotation or a zero translation part (e.g. --sigma 0/1), or with
//    StudyOptions::estimate_noise, nothing is given and Calibrate estimates the noise from the
//    residuals.
// Noise kinds: kPnp is the camera's noise shape (sim/noise.h); with it the robot poses get
// Gaussian noise of the same level. The sigmas below are the per-component RMS of the kind
// (for kPnp √((2² + 2² + 0.1²)/3) σ_r and √((0.5² + 0.5² + 5²)/3) σ_t).
estimation::PoseSigma RobotSigma(const Setting& setting);
estimation::PoseSigma CameraSigma(const Setting& setting);

struct StudyOptions {
  std::vector<Setting> settings;
  std::vector<estimation::Method> methods;  // in report order
  int trials = 200;
  uint64_t seed = 1;
  int threads = 0;  // 0: std::thread::hardware_concurrency()
  // The covariance each trial predicts for X: method nullopt = each method's default
  // (estimation::DefaultCovarianceMethod); kNone (the default) = none, no consistency columns.
  estimation::CovarianceOptions covariance = NoCovariance();
  // Every method through estimation::Calibrate with its outlier rejection (station_selection.h);
  // false: the estimators alone (the thesis study), closed forms straight to their solver.
  bool reject_outliers = false;
  // Tell no method the noise: Calibrate estimates it from the residuals (hecal's default path).
  bool estimate_noise = false;

  static estimation::CovarianceOptions NoCovariance() {
    estimation::CovarianceOptions options;
    options.method = estimation::CovarianceMethod::kNone;
    return options;
  }
};

// Throws InputError (source "--<flag>") when options are unusable: no setting, no method,
// trials < 1, stations < 3, negative sigma, gross outliers < 0 or leaving fewer than 3 good
// stations, covariance options (estimation::CovarianceOptions::IsValid).
void ValidateStudyOptions(const StudyOptions& options);

enum class TrialStatus { kOk, kThrew, kNonFinite };
std::string_view TrialStatusName(TrialStatus status);

struct TrialResult {
  int setting = 0;  // index into StudyOptions::settings
  int trial = 0;
  estimation::Method method = estimation::Method::kMl;
  TrialStatus status = TrialStatus::kOk;
  std::string message;             // exception text when kThrew
  double rotation_error = 0.0;     // radians, NaN unless kOk
  double translation_error = 0.0;  // metres, NaN unless kOk
  // Triangle threshold (sim/triangle_threshold.h) on this setting's and method's rotation OR
  // translation errors; errors below 1e-9 rad / 1e-9 m are rounding noise and never outliers.
  bool outlier = false;
  // With a covariance (StudyOptions::covariance): e = Log(X̂⁻¹ X̃), its predicted covariance,
  // and the NEES eᵀ Σ⁻¹ e (NaN otherwise, or when Σ is singular).
  Vector6d error_X = Vector6d::Constant(std::numeric_limits<double>::quiet_NaN());
  std::optional<Matrix6d> covariance_X;
  double nees = std::numeric_limits<double>::quiet_NaN();
  // The covariance of X from the noise model alone (before the model check,
  // estimation/model_check.h), its NEES, and whether the check inflated the reported one.
  std::optional<Matrix6d> covariance_X_model;
  double nees_model = std::numeric_limits<double>::quiet_NaN();
  bool check_used = false;
  // The robot noise the method's covariance assumed: given, or estimated from the residuals
  // (StudyOptions::estimate_noise); zero for closed forms solved without Calibrate.
  estimation::PoseSigma robot_sigma;
  // With gross outliers or reject_outliers: the stations the method rejected, split into the
  // replaced ones and good ones, and (gross outliers only) the errors of the same method on
  // the same data set without the replaced stations.
  int rejected_outliers = 0;
  int rejected_good = 0;
  double rotation_error_clean = std::numeric_limits<double>::quiet_NaN();
  double translation_error_clean = std::numeric_limits<double>::quiet_NaN();
};

// A rotation and a translation magnitude: an error against the truth, or a bound.
struct RotationTranslation {
  double rotation = 0.0;     // radians
  double translation = 0.0;  // metres
};

// First-order bound of one trial's data set: sqrt(trace) of the rotation and translation blocks
// of the covariance of X from the ml information matrix at the truth — the RMS error an
// efficient estimator reaches to first order. NaN when the information matrix is singular.
using Bound = RotationTranslation;

struct MethodSummary {
  int setting = 0;
  estimation::Method method = estimation::Method::kMl;
  int trials = 0;
  int failures = 0;
  int outliers = 0;
  sim::SummaryStatistics rotation;        // radians, over every finite trial (outliers included)
  sim::SummaryStatistics translation;     // metres
  double rotation_rmse_inliers = 0.0;     // radians, outliers removed (the thesis' statistic)
  double translation_rmse_inliers = 0.0;  // metres
  // Worst trial relative to its own bound: max over trials of error / bound (NaN without bound).
  double worst_rotation_over_bound = 0.0;
  double worst_translation_over_bound = 0.0;
  // With a covariance: the consistency of the predicted covariances of X with the errors, over
  // the trials that succeeded (outliers included: a covariance should cover them too).
  std::optional<uncertainty::Consistency> consistency;
  // The same for the model-only covariance, and the trials in which the model check inflated
  // the reported covariance.
  std::optional<uncertainty::Consistency> consistency_model;
  int check_used = 0;
  // Outlier rejection over the successful trials: gross outliers injected and rejected, good
  // stations and good stations rejected, trials in which every gross outlier was rejected, and
  // the RMS errors without the replaced stations (NaN without gross outliers).
  int outliers_injected = 0;
  int outliers_rejected = 0;
  int good_stations = 0;
  int good_rejected = 0;
  int trials_all_found = 0;
  double rotation_rmse_clean = std::numeric_limits<double>::quiet_NaN();
  double translation_rmse_clean = std::numeric_limits<double>::quiet_NaN();
};

struct StudyResult {
  StudyOptions options;
  std::vector<TrialResult> trials;         // setting-major, then trial, then method
  std::vector<std::vector<Bound>> bounds;  // [setting][trial]
  std::vector<Bound> setting_bounds;       // per setting: RMS of the trial bounds
  std::vector<MethodSummary> summaries;    // setting-major, then method
};

// The noise a setting puts on the robot poses and on the camera poses (sim/noise.h; zero for a
// device without noise, NoiseOn; kPnp shapes the camera's only).
sim::NoiseModel RobotNoise(const Setting& setting);
sim::NoiseModel CameraNoise(const Setting& setting);

// The data set of one trial of `setting` before any gross outlier: the thesis protocol with the
// setting's setup, stations and noise, drawn from `rng` (RunStudy seeds it with TrialSeed).
sim::SimulatedData SimulateTrial(const Setting& setting, std::mt19937_64& rng);

// What a method is told when it solves a trial through estimation::Calibrate: `study`'s
// covariance on one thread, its outlier rejection, the model check with a covariance, and the
// setting's sigmas unless study.estimate_noise (RobotSigma above).
estimation::CalibrateOptions TrialCalibrateOptions(estimation::Method method,
                                                   const Setting& setting,
                                                   const StudyOptions& study);

// Runs every trial of every setting; throws InputError for invalid options.
StudyResult RunStudy(const StudyOptions& options);

// The per-trial seed (exposed for tests and for regenerating one trial's data).
uint64_t TrialSeed(uint64_t seed, handeye::Setup setup, int stations, int trial);

// Rotation angle of R̃⁻¹R̂ and translation distance of an estimate against the truth.
RotationTranslation PoseError(const Pose& estimate, const Pose& truth);

}  // namespace hecal::study
