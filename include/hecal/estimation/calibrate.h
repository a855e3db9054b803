// hecal's top-level hand–eye calibration: any method by name, residuals, outlier flags,
// warnings. This is what `hecal calibrate` calls (docs/result-file.md).
//
// Methods (by name: methods.h): the closed-form solvers through handeye::SolveClosedForm;
// `strobl` (strobl.h) and `ml` (ml.h, the default) refined from every closed-form solution that
// succeeds (initialization.h). Degenerate data are rejected first (handeye::CheckObservability).
//
// Residual of station i (problem.h, Z = A_i X B_i):  r_i = Log(Z⁻¹ · A_i · X · B_i) ∈ R⁶, (ω, v)
// order, right perturbation of Z. Reported per station: the rotation angle |ω| and the
// translation |t| of Z⁻¹ A_i X B_i (the target pose predicted by station i, seen from the
// estimate), and the whitened residual sqrt(r_iᵀ Σ_i⁻¹ r_i / 6) with Σ_i the first-order
// covariance of r_i under the noise model (station_covariance.h): ≈ 1 for an inlier.
// Noise model: --robot-sigma / --camera-sigma when given; otherwise estimated from the residuals
// (noise_estimation.h; equal split between robot and camera — only their combined effect is
// identifiable from poses) and a warning says so.
// Covariance: of (X, Z) under that noise model, by options.covariance (default: ml's analytic
// information, the UT through the solver for every other method; calibration_covariance.h),
// then checked against a delete-group jackknife over the stations used, which does not trust
// the noise model, and inflated per axis when the model understates it (model_check.h; with
// ≤ 6 stations a warning says no check is possible).
// A solver that throws at a UT sigma point or a linearisation step makes Calibrate throw that
// error (Monte Carlo instead counts such samples and warns).
// Outliers: by default gross outliers are rejected first (station_selection.h: consensus over
// minimal station sets, then a χ² test of every station at the noise of the others) and the
// method runs on the stations that remain (for ml the selection's own fit when it is that very
// solve: station_selection.h, "Reuse"); the rejected are listed with their residuals at the
// result. The degeneracy check runs on the stations used. With reject_outliers = false every
// station is used. Among the used stations one is still flagged when its studentised residual
// exceeds the 3σ level (the χ² quantile of p = 0.0027 for its degrees of freedom;
// noise_estimation.h) at the chosen method's estimate; a warning lists them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/covariance_method.h"
#include "hecal/estimation/methods.h"
#include "hecal/estimation/model_check.h"
#include "hecal/estimation/noise_estimation.h"
#include "hecal/estimation/pose_sigma.h"
#include "hecal/estimation/robust_loss.h"
#include "hecal/estimation/station_selection.h"
#include "hecal/estimation/target_scale.h"
#include "hecal/geometry/types.h"
#include "hecal/handeye/certificate.h"
#include "hecal/handeye/planar.h"
#include "hecal/handeye/problem.h"

namespace hecal::estimation {

struct CalibrateOptions {
  Method method = Method::kMl;
  std::optional<PoseSigma> robot_sigma;   // --robot-sigma; estimated when absent
  std::optional<PoseSigma> camera_sigma;  // --camera-sigma; estimated when absent
  // Robust loss for ml (robust_loss.h); scale in whitened units per component (the default
  // down-weights exactly the stations beyond the outlier level).
  RobustLoss robust_loss = RobustLoss::kNone;
  double robust_scale = kOutlierLevelScale;
  // How the covariance of (X, Z) is computed (calibration_covariance.h).
  CovarianceOptions covariance;
  // Reject gross outliers before solving (station_selection.h); false: --keep-outliers.
  bool reject_outliers = true;
  handeye::ConsensusOptions consensus;  // its hypotheses and seed
  // Check the covariance against a delete-group jackknife over stations and inflate it when the
  // noise model understates it (model_check.h). false: the model's covariance alone (solver
  // timing, studies that need the solve only).
  bool model_check = true;
  // Station names for warnings, one per station of the problem (default: numbers from 1).
  std::vector<std::string> station_ids;
  // Planar robots (handeye/planar.h, docs/planar.md): one component of X's translation given
  // (--fix tz=VALUE), metres in X's parent frame; method ml only.
  std::optional<handeye::TranslationFix> fix;
  // The target's printed scale (target_scale.h, docs/target-scale.md; --target-scale).
  TargetScaleMode target_scale = TargetScaleMode::kFit;
  double given_target_scale = 1.0;  // with kGiven: the measured print ÷ the described size

  // core/options_check.h: false naming CalibrateOptions.robot_sigma / .camera_sigma (outside
  // pose_sigma.h's range, or both zero in rotation or in translation: a singular noise model),
  // .robust_scale (not positive and finite), .fix (an axis other than 0–2, a value not finite,
  // or a method other than ml), .given_target_scale (not in (0.5, 2)), or a CovarianceOptions or
  // ConsensusOptions field.
  bool IsValid(std::string* why) const;
};

struct StationResidual {
  double rotation = 0.0;     // radians, |ω| of r_i
  double translation = 0.0;  // metres, |translation of Z⁻¹ A_i X B_i|
  double whitened = 0.0;     // sqrt(r_iᵀ Σ_i⁻¹ r_i / 6): ≈ 1 for an inlier
  bool outlier = false;      // studentised residual beyond the 3σ level
};

struct CalibrationResult {
  Method method = Method::kMl;
  Pose X = Pose::Identity();
  Pose Z = Pose::Identity();
  // Right-perturbation covariance of (X, Z), (rx, ry, rz, tx, ty, tz) each, radians and
  // metres, under the noise model robot_sigma / camera_sigma (calibration_covariance.h).
  // Absent only with CovarianceMethod::kNone. When model_check->used, this is the model's
  // covariance inflated per axis by the check (model_check.h).
  std::optional<CalibrationCovariance> covariance;
  // The check of that covariance against a jackknife over stations (absent with
  // options.model_check false or no covariance).
  std::optional<ModelCheck> model_check;
  std::vector<StationResidual> residuals;  // one per USED station, in problem order
  double rotation_rms = 0.0;               // radians
  double translation_rms = 0.0;            // metres
  PoseSigma robot_sigma;                   // used (given or estimated)
  PoseSigma camera_sigma;                  // used (given or estimated)
  // The camera's tilt (rotation) / depth (translation) excess σ of the anisotropic noise model
  // (noise_estimation.h), in the camera frame; zero when the isotropic model was used.
  PoseSigma camera_excess;
  // The heavy-tailed noise model (student_t.h) when ml chose it: ν (0: Gaussian) and, per used
  // station, the multiplier κ_ν / w_i of its covariance (empty: 1); robot_sigma and camera_sigma
  // are then the t model's scale.
  double student_t_dof = 0.0;
  std::vector<double> station_scale;
  bool sigmas_estimated = false;
  // Stations left out by the outlier rejection (indices into the problem, ascending) and their
  // residuals at (X, Z), whitened by the noise model of the result.
  std::vector<int> rejected;
  std::vector<StationResidual> rejected_residuals;
  std::vector<std::string> rejected_ids;  // their options.station_ids (empty when none given)
  bool outlier_rejection = false;         // the rejection ran (reject_outliers and n ≥ 5)
  // The seed of the randomness the result used (the consensus's random triples, a Monte Carlo
  // covariance), when it used any.
  std::optional<std::uint64_t> seed;
  std::vector<std::string> warnings;
  // With CalibrateOptions::fix: the fixed component and the directions of the family (planar.h,
  // (P1)) the data cannot tell apart; the covariance is zero along the fixed coordinate.
  std::optional<handeye::FixedTranslation> fixed;
  // The target's scale as measured from the robot's motion (absent with --fix, with
  // TargetScaleMode::kGiven and below 3 stations), and the scale the answer uses: the camera
  // translations were multiplied by `applied_target_scale` (1: the described size). With a
  // measured scale applied, the covariance of (X, Z) includes the scale's uncertainty.
  std::optional<TargetScale> target_scale;
  double applied_target_scale = 1.0;
  // The certificate of global optimality of the chordal problem at the answer
  // (handeye/certificate.h; absent with --fix). When it fails, `global_optimum` is the lowest
  // certified minimum reached from the closed-form starts, if any (its X and Z: `polished`).
  std::optional<handeye::Certificate> certificate;
  std::optional<handeye::Certificate> global_optimum;
};

// Throws hecal::DegenerateError on degenerate data (handeye/observability.h), hecal::InputError
// when !options.IsValid (its source the field), when the problem's robot and camera pose counts
// differ, or when options.covariance.method does not fit that many stations (CheckCovarianceFits).
CalibrationResult Calibrate(const handeye::Problem& problem, const CalibrateOptions& options);

// The same with the stations already selected (SelectStations or AllStations): `--method all`
// selects once and runs every method on the same stations. options.reject_outliers is ignored.
CalibrationResult Calibrate(const handeye::Problem& problem, const CalibrateOptions& options,
                            const StationSelection& selection);

// The selection Calibrate makes for `options`: SelectStations with the given sigmas and
// options.consensus, or AllStations when options.reject_outliers is false.
StationSelection SelectStationsFor(const handeye::Problem& problem,
                                   const CalibrateOptions& options);

// Sets result->certificate (handeye/certificate.h) for the answer's X, Z on `problem` (the
// stations used, at the target scale applied), weighted by the result's noise; when it fails,
// certifies the closed-form starts and keeps the lowest certified as result->global_optimum,
// with a warning when that optimum costs less than the answer's.
void CertifyResult(const handeye::Problem& problem, CalibrationResult* result);

// Fills result->residuals, rotation_rms and translation_rms at result->X, result->Z, with the
// whitened residuals and outlier flags of `noise` (noise_estimation.h, linearised at the same
// X, Z); returns the indices of the flagged stations.
std::vector<int> SetStationResiduals(const handeye::Problem& problem, const NoiseEstimate& noise,
                                     CalibrationResult* result);

// The residuals at (X, Z) of the stations not `used`, whitened by the noise model `variances`
// (the prediction from the used stations' fit is the statistic; `whitened` is
// sqrt(r_iᵀ Σ_i⁻¹ r_i / 6)), in station order; empty when every station is used.
std::vector<StationResidual> RejectedResiduals(const handeye::Problem& problem,
                                               const std::vector<bool>& used, const Pose& X,
                                               const Pose& Z, const NoiseVariances& variances);

}  // namespace hecal::estimation
