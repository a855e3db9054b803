#include "hecal/estimation/calibrate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/estimation/calibration_covariance.h"
#include "hecal/estimation/initialization.h"
#include "hecal/estimation/ml.h"
#include "hecal/estimation/noise_estimation.h"
#include "hecal/estimation/robust_loss.h"
#include "hecal/estimation/station_selection.h"
#include "hecal/estimation/strobl.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"
#include "hecal/handeye/observability.h"
#include "hecal/handeye/station_consensus.h"

namespace hecal::estimation {
namespace {

bool SameSigma(const std::optional<PoseSigma>& a, const std::optional<PoseSigma>& b) {
  if (!a || !b) return !a && !b;
  return a->rotation == b->rotation && a->translation == b->translation;
}

std::string Format(const char* format, double a, double b) {
  char buffer[128];
  std::snprintf(buffer, sizeof(buffer), format, a, b);
  return buffer;
}

std::string SigmaText(const PoseSigma& sigma) {
  return Format("%.3g deg, %.3g mm", sigma.rotation * kDegreesPerRadian, sigma.translation * 1e3);
}

// The richer and the heavy-tailed noise model of the result (noise_estimation.h, student_t.h),
// for the noise warning; empty when the isotropic Gaussian model was kept.
std::string RicherModelText(const NoiseEstimate& noise) {
  std::string text;
  if (noise.richer) {
    text = "; the residuals chose a richer model than isotropic noise (likelihood ratio " +
           Format("%.3g", noise.likelihood_ratio, 0.0) + ")";
    const PoseSigma excess = noise.camera_excess();
    if (excess.rotation > 0.0 || excess.translation > 0.0)
      text += ": the camera has an excess of " + SigmaText(excess) +
              " in tilt (about its x, y) and depth (along its z)";
  }
  if (noise.student_t_dof > 0.0) {
    text += "; the residuals are heavy-tailed: a Student-t model with " +
            Format("%.3g", noise.student_t_dof, 0.0) +
            " degrees of freedom was chosen over the Gaussian (likelihood ratio " +
            Format("%.3g", noise.student_t_ratio, 0.0) +
            "), the sigmas are its scale and stations far out are down-weighted";
  }
  return text;
}

// The per-station noise of `result`'s model: the robot's and the camera's isotropic sigmas, and
// the camera's tilt / depth excess turned into each camera pose's frame (station_covariance.h).
StationNoise ResultStationNoise(const handeye::Problem& problem, const CalibrationResult& result) {
  StationNoise noise =
      StationNoise::Uniform(problem.A.size(), result.robot_sigma, result.camera_sigma);
  const NoiseVariances excess = Variances({}, {}, result.camera_excess);
  if (excess[kCameraTiltExcess] != 0.0 || excess[kCameraDepthExcess] != 0.0) {
    for (size_t i = 0; i < problem.A.size(); ++i) {
      const NoiseComponents Q =
          StationNoiseComponents(problem.setup, problem.A[i], problem.B[i], result.X);
      noise.camera[i] += excess[kCameraTiltExcess] * Q[kCameraTiltExcess] +
                         excess[kCameraDepthExcess] * Q[kCameraDepthExcess];
    }
  }
  for (size_t i = 0; i < result.station_scale.size(); ++i) {
    noise.robot[i] *= result.station_scale[i];
    noise.camera[i] *= result.station_scale[i];
  }
  return noise;
}

// Station names for messages: options.station_ids when given, else numbers from 1.
std::string StationList(const std::vector<int>& stations, const CalibrateOptions& options) {
  std::string text;
  for (size_t k = 0; k < stations.size(); ++k) {
    if (k > 0) text += k + 1 == stations.size() ? " and " : ", ";
    const size_t i = static_cast<size_t>(stations[k]);
    text += i < options.station_ids.size() ? options.station_ids[i] : std::to_string(i + 1);
  }
  return text;
}

// Checks the options and what the problem asks of them.
void ValidateOptions(const handeye::Problem& problem, const CalibrateOptions& options) {
  RequireValid(options);
  if (problem.A.size() != problem.B.size()) {
    throw InputError("stations", 0, "the numbers of robot and camera poses differ",
                     "give one camera pose per robot pose");
  }
  if (options.covariance.method) {
    CheckCovarianceFits(*options.covariance.method, options.method, problem.A.size());
  }
}

}  // namespace

bool CalibrateOptions::IsValid(std::string* why) const {
  if (!SigmaIsValid(robot_sigma, "CalibrateOptions.robot_sigma", why) ||
      !SigmaIsValid(camera_sigma, "CalibrateOptions.camera_sigma", why)) {
    return false;
  }
  if (robot_sigma && camera_sigma &&
      (robot_sigma->rotation + camera_sigma->rotation == 0.0 ||
       robot_sigma->translation + camera_sigma->translation == 0.0)) {
    return Invalid(why, "CalibrateOptions.robot_sigma",
                   "the robot and camera sigmas are both zero in rotation or in translation, so "
                   "the noise model is singular",
                   "give a non-zero value, or leave both sigmas unset to estimate the noise");
  }
  if (!(robust_scale > 0.0) || !std::isfinite(robust_scale)) {
    return Invalid(why, "CalibrateOptions.robust_scale", "the robust loss scale must be positive",
                   "use e.g. 1.83 (whitened units per component: the 3-sigma outlier level)");
  }
  if (fix && (fix->axis < 0 || fix->axis > 2 || !std::isfinite(fix->value))) {
    return Invalid(why, "CalibrateOptions.fix",
                   "the fixed component must be tx, ty or tz with a "
                   "finite value",
                   "give e.g. tz=0.12 (metres)");
  }
  if (fix && method != Method::kMl) {
    return Invalid(
        why, "CalibrateOptions.fix",
        "a fixed translation component needs the method ml, not " + std::string(Info(method).name),
        "use --method ml (the default)");
  }
  if (target_scale == TargetScaleMode::kGiven &&
      !(given_target_scale > 0.5 && given_target_scale < 2.0)) {
    return Invalid(why, "CalibrateOptions.given_target_scale",
                   "the target's scale (measured ÷ described size) must be between 0.5 and 2",
                   "give e.g. 0.96 for a board printed at 96 % of its described size");
  }
  return covariance.IsValid(why) && consensus.IsValid(why);
}

std::vector<int> SetStationResiduals(const handeye::Problem& problem, const NoiseEstimate& noise,
                                     CalibrationResult* result) {
  const size_t n = problem.A.size();
  result->residuals.resize(n);
  double rotation_sum = 0.0, translation_sum = 0.0;
  std::vector<int> flagged;
  for (size_t i = 0; i < n; ++i) {
    const Pose E = result->Z.inverse() * problem.A[i] * result->X * problem.B[i];
    StationResidual& residual = result->residuals[i];
    residual.rotation = se3::Log(E).head<3>().norm();
    residual.translation = E.translation().norm();
    residual.whitened = std::sqrt(noise.stations[i].chi2 / 6.0);
    residual.outlier = noise.stations[i].outlier;
    rotation_sum += residual.rotation * residual.rotation;
    translation_sum += residual.translation * residual.translation;
    if (residual.outlier) flagged.push_back(static_cast<int>(i));
  }
  result->rotation_rms = std::sqrt(rotation_sum / static_cast<double>(n));
  result->translation_rms = std::sqrt(translation_sum / static_cast<double>(n));
  return flagged;
}

StationSelection SelectStationsFor(const handeye::Problem& problem,
                                   const CalibrateOptions& options) {
  if (!options.reject_outliers || problem.A.size() != problem.B.size())
    return AllStations(problem.A.size());
  StationSelectionOptions selection_options;
  selection_options.robot_sigma = options.robot_sigma;
  selection_options.camera_sigma = options.camera_sigma;
  selection_options.consensus = options.consensus;
  selection_options.fix = options.fix;
  return SelectStations(problem, selection_options);
}

std::vector<StationResidual> RejectedResiduals(const handeye::Problem& problem,
                                               const std::vector<bool>& used, const Pose& X,
                                               const Pose& Z, const NoiseVariances& variances) {
  std::vector<StationResidual> residuals;
  if (std::find(used.begin(), used.end(), false) == used.end()) return residuals;
  const std::vector<StationTest> tests =
      TestStations(LinearizeStations(problem, X, Z), used, variances);
  for (size_t i = 0; i < used.size(); ++i) {
    if (used[i]) continue;
    const handeye::StationError size = handeye::StationResidualSize(problem, i, {X, Z});
    residuals.push_back({size.rotation, size.translation, std::sqrt(tests[i].chi2 / 6.0), true});
  }
  return residuals;
}

CalibrationResult Calibrate(const handeye::Problem& problem, const CalibrateOptions& options) {
  ValidateOptions(problem, options);
  return Calibrate(problem, options, SelectStationsFor(problem, options));
}

namespace {

// The calibration at the target size the camera poses carry (target_scale.h: scale 1).
CalibrationResult CalibrateAtDescribedSize(const handeye::Problem& all_stations,
                                           const CalibrateOptions& options,
                                           const StationSelection& selection) {
  const RobustLoss loss = options.robust_loss;
  const handeye::Problem problem = handeye::SubProblem(all_stations, selection.used);
  handeye::CheckObservability(problem, options.fix.has_value());

  CalibrationResult result;
  if (options.fix) result.fixed = handeye::ResolveFix(problem, *options.fix);
  result.method = options.method;
  result.rejected = selection.Rejected();
  result.outlier_rejection = selection.rounds > 0 || selection.too_many;
  if (result.outlier_rejection) result.seed = options.consensus.seed;
  const NoiseSpec spec = NoiseSpec::FromSigmas(options.robot_sigma, options.camera_sigma);
  const double L = handeye::LengthScale(problem);
  NoiseEstimate noise;
  std::optional<Eigen::Matrix<double, 12, 12>> ml_covariance;
  if (options.method == Method::kMl) {
    MlOptions ml_options;
    ml_options.robot_sigma = options.robot_sigma;
    ml_options.camera_sigma = options.camera_sigma;
    ml_options.robust_loss = loss;
    ml_options.robust_scale = options.robust_scale;
    ml_options.fixed = result.fixed;
    // The selection's own fit is this very solve when it was made on the same stations from
    // the same starts with the same noise model (station_selection.h).
    const bool reuse = selection.fit && loss == RobustLoss::kNone &&
                       SameSigma(selection.fit_robot_sigma, options.robot_sigma) &&
                       SameSigma(selection.fit_camera_sigma, options.camera_sigma);
    const std::vector<handeye::Solution> starts =
        result.fixed ? std::vector<handeye::Solution>{handeye::FixedStart(problem, *result.fixed)}
                     : StartingSolutions(problem);
    MlResult ml = reuse ? *selection.fit : RefineMl(problem, starts, ml_options);
    // The selection's fit is Gaussian (station_selection.h): the heavy-tail stage on top.
    if (reuse) FitHeavyTails(problem, ml_options, &ml);
    result.X = ml.X;
    result.Z = ml.Z;
    ml_covariance = ml.covariance;
    noise = ml.noise;
  } else {
    handeye::Solution solution;
    if (options.method == Method::kStrobl) {
      const StroblResult strobl = RefineStrobl(problem, ClosedFormStarts(problem));
      solution = {strobl.X, strobl.Z};
    } else {
      solution = handeye::SolveClosedForm(*Info(options.method).closed_form, problem);
    }
    result.X = solution.X;
    result.Z = solution.Z;
    noise = EstimateNoise(LinearizeStations(problem, result.X, result.Z), spec, L);
  }

  std::vector<int> flagged = SetStationResiduals(problem, noise, &result);
  const size_t n = problem.A.size();
  result.rejected_residuals =
      RejectedResiduals(all_stations, selection.used, result.X, result.Z, noise.variances);
  for (int i : result.rejected) {
    if (static_cast<size_t>(i) < options.station_ids.size())
      result.rejected_ids.push_back(options.station_ids[static_cast<size_t>(i)]);
  }
  // Flagged stations by their index in the whole problem.
  const std::vector<int> used_index = TrueIndices(selection.used);
  for (int& i : flagged) i = used_index[i];
  result.robot_sigma = noise.robot();
  result.camera_sigma = noise.camera();
  result.camera_excess = noise.camera_excess();
  result.student_t_dof = noise.student_t_dof;
  result.station_scale = noise.station_scale;
  result.sigmas_estimated = spec.AnyEstimated();
  // The covariance of (X, Z) under that noise model: ml's analytic information when linear,
  // else propagated through the solver (calibration_covariance.h).
  const CovarianceMethod covariance_method =
      options.covariance.method.value_or(DefaultCovarianceMethod(options.method, n));
  if (ml_covariance && covariance_method == CovarianceMethod::kLinear) {
    CalibrationCovariance covariance;
    covariance.covariance = *ml_covariance;
    result.covariance = covariance;
  } else {
    result.covariance = PropagateCovariance(
        problem, result, options, ResultStationNoise(problem, result), options.covariance);
  }
  if (result.covariance && options.model_check) ApplyModelCheck(problem, options, &result);
  if (result.covariance && result.covariance->method == CovarianceMethod::kMonteCarlo)
    result.seed = options.covariance.seed;
  if (result.covariance) {
    if (std::string warning = FailedSamplesWarning(*result.covariance); !warning.empty()) {
      result.warnings.push_back(std::move(warning));
    }
  }
  // Now that the robot noise is known (given or estimated): is every direction of X's
  // translation observed by more than noise? (observability.h)
  if (std::string weak = handeye::CheckObservabilityUnderNoise(problem, result.robot_sigma.rotation,
                                                               result.fixed.has_value());
      !weak.empty()) {
    result.warnings.push_back(std::move(weak));
  }

  // Warnings.
  if (!options.robot_sigma && !options.camera_sigma) {
    result.warnings.push_back(
        "noise not given (--robot-sigma, --camera-sigma): estimated from the residuals as " +
        SigmaText(result.robot_sigma) + " per component for the robot and " +
        SigmaText(result.camera_sigma) +
        " for the camera (from poses alone the split of the translation noise is not "
        "identifiable, so it is equal; the rotation noise is split equally unless the residuals "
        "tell the two apart)" +
        RicherModelText(noise));
  } else if (!options.camera_sigma) {
    result.warnings.push_back(
        "camera noise not given (--camera-sigma): estimated from the "
        "residuals as " +
        SigmaText(result.camera_sigma) + " per component" + RicherModelText(noise));
  } else if (!options.robot_sigma) {
    result.warnings.push_back(
        "robot noise not given (--robot-sigma): estimated from the "
        "residuals as " +
        SigmaText(result.robot_sigma) + " per component");
  }
  if (loss != RobustLoss::kNone && options.method != Method::kMl) {
    result.warnings.push_back("the robust loss applies to ml only; ignored for " +
                              std::string(Info(options.method).name));
  }
  if (!noise.converged) {
    result.warnings.push_back("the noise estimate did not converge; sigmas are approximate");
  }
  if (!flagged.empty()) {
    if (flagged.size() > (n - 3) / 2) {
      result.warnings.push_back(
          std::to_string(flagged.size()) + " of " + std::to_string(n) +
          " stations have residuals beyond 3 sigma of the noise model: " +
          (spec.AnyEstimated() ? std::string("the residuals do not fit the noise model")
                               : std::string("the given sigmas are too small")) +
          ", or the pose conventions are wrong (try inverting the robot or camera poses)");
    } else {
      const bool one = flagged.size() == 1;
      result.warnings.push_back(
          std::string(one ? "station " : "stations ") + StationList(flagged, options) + " " +
          (one ? "has" : "have") + " residuals beyond 3 sigma of the noise model at the " +
          std::string(Info(options.method).name) + " estimate (flagged, still used: " +
          (result.outlier_rejection
               ? "the outlier test at the ml fit passed " + std::string(one ? "it" : "them")
               : std::string("outlier rejection is off")) +
          ")");
    }
  }
  if (!result.rejected.empty()) {
    const bool one = result.rejected.size() == 1;
    std::string text = std::string(one ? "station " : "stations ") +
                       StationList(result.rejected, options) + " rejected as " +
                       (one ? "an outlier" : "outliers") + " (residual ";
    for (size_t k = 0; k < result.rejected_residuals.size(); ++k) {
      const StationResidual& r = result.rejected_residuals[k];
      if (k > 0) text += "; ";
      text += Format("%.3g deg / %.3g mm", r.rotation * kDegreesPerRadian, r.translation * 1e3);
    }
    result.warnings.push_back(text + ", beyond 3 sigma of the noise of the other stations): " +
                              "check their robot pose, detection and pairing");
  }
  if (selection.too_many) {
    result.warnings.push_back(
        std::to_string(selection.flagged) + " of " + std::to_string(all_stations.A.size()) +
        " stations fail the outlier test, more than can be rejected: the data as a whole do not "
        "fit one rigid setup under the noise model (check the setup, the pose conventions, the "
        "pairing of robot and camera rows, and the sigmas); every station was used");
  }
  return result;
}

std::string ScalePercent(double value) {
  return Format("%.2f %%", 100.0 * value, 0.0);
}

// The warning on a measured scale that refutes the described one (empty when it does not).
std::string TargetScaleWarning(const TargetScale& scale, bool applied) {
  if (!scale.Mismatch()) return "";
  const std::string measured =
      "the robot's motion measures the target at " + ScalePercent(scale.scale) + " ± " +
      ScalePercent(scale.sigma) + " (1σ) of the size its description states, " +
      Format("%.1fσ", std::abs(scale.scale - 1.0) / scale.sigma, 0.0) + " from it";
  if (!applied) {
    return measured +
           "; X and Z are given at the described size as --target-scale stated asks, and their "
           "σ does not cover the difference";
  }
  if (std::abs(scale.scale - 1.0) < kPrinterTolerance) {
    return measured + " (within a printer's tolerance of ±" + ScalePercent(kPrinterTolerance) +
           "): X and Z are given at the measured size, their σ including the scale's";
  }
  return "the target is not the size its description states: " + measured +
         ". A print scaled to fit the page (94–97 %) is the common cause. X and Z are given at "
         "the measured size, their σ including the scale's. Fix: measure the printed target "
         "(e.g. ten squares with calipers) and set its size (square: or the marker size in the "
         "target description) to the measured value before detecting the poses; if the print "
         "was measured and the description is right, pass --target-scale stated";
}

}  // namespace

// The certificate of the answer (handeye/certificate.h), weighted by the result's noise; when
// it fails, the closed-form starts polished and certified in turn, the lowest certified kept as
// `global_optimum`, and a warning when that optimum is not the answer's.
void CertifyResult(const handeye::Problem& problem, CalibrationResult* result) {
  const double rotation = std::hypot(result->robot_sigma.rotation, result->camera_sigma.rotation);
  const double translation =
      std::hypot(result->robot_sigma.translation, result->camera_sigma.translation);
  const handeye::ChordalWeights weights =
      handeye::WeightsFromSigmas(rotation, translation, handeye::LengthScale(problem));
  result->certificate = handeye::CertifyGlobalOptimum(problem, {result->X, result->Z}, weights);
  if (result->certificate->certified) return;
  for (const handeye::Solution& start : ClosedFormStarts(problem)) {
    const handeye::Certificate other = handeye::CertifyGlobalOptimum(problem, start, weights);
    if (other.certified && (!result->global_optimum || other.cost < result->global_optimum->cost))
      result->global_optimum = other;
  }
  if (!result->global_optimum) {
    result->warnings.push_back(
        "the answer could not be certified globally optimal (the dual of the chordal least "
        "squares is not tight at it, nor at any closed-form start): with data this noisy or "
        "this close to degenerate, compare --method all and add stations that rotate about "
        "different axes");
    return;
  }
  const handeye::Certificate& best = *result->global_optimum;
  const double rotation_off =
      so3::Log(result->X.linear().transpose() * best.polished.X.linear()).norm();
  const double translation_off = (result->X.translation() - best.polished.X.translation()).norm();
  if (best.cost < result->certificate->cost * (1.0 - 1e-6)) {
    result->warnings.push_back(
        "the answer is not the global optimum: the chordal least squares has a certified global "
        "minimum " +
        Format("%.3g deg / %.3g mm", rotation_off * kDegreesPerRadian, translation_off * 1e3) +
        " from X (certificate.global_optimum); the answer lies in another basin — check the data "
        "for a wrong station or a degenerate motion, and compare --method all");
  }
}

CalibrationResult Calibrate(const handeye::Problem& all_stations, const CalibrateOptions& options,
                            const StationSelection& selection) {
  ValidateOptions(all_stations, options);
  if (options.target_scale == TargetScaleMode::kGiven) {
    CalibrationResult result = CalibrateAtDescribedSize(
        ScaleCameraTranslations(all_stations, options.given_target_scale), options, selection);
    result.applied_target_scale = options.given_target_scale;
    if (!options.fix) {
      CertifyResult(ScaleCameraTranslations(handeye::SubProblem(all_stations, selection.used),
                                            options.given_target_scale),
                    &result);
    }
    return result;
  }
  if (options.fix) {  // planar robots: X's translation is not fully observed
    return CalibrateAtDescribedSize(all_stations, options, selection);
  }
  // With kFit the described-size pass only starts the scale estimate (X, Z and the noise): no
  // covariance, no model check; it is run in full only when the scale is not observable.
  CalibrateOptions first = options;
  if (options.target_scale == TargetScaleMode::kFit) {
    first.covariance.method = CovarianceMethod::kNone;
    first.model_check = false;
  }
  CalibrationResult result = CalibrateAtDescribedSize(all_stations, first, selection);
  const TargetScale scale =
      EstimateTargetScale(handeye::SubProblem(all_stations, selection.used), result.X, result.Z,
                          Variances(result.robot_sigma, result.camera_sigma, result.camera_excess),
                          result.station_scale, result.sigmas_estimated);
  const bool apply = scale.observable && options.target_scale == TargetScaleMode::kFit;
  if (apply) {
    // The same stations; the selection's own ml fit was made at the described size.
    StationSelection rescaled = selection;
    rescaled.fit.reset();
    CalibrationResult measured = CalibrateAtDescribedSize(
        ScaleCameraTranslations(all_stations, scale.scale), options, rescaled);
    if (measured.covariance) {
      // The covariance at a known scale plus the scale's share: Cov(δ | s) + g σ_ε² gᵀ.
      const double log_sigma = scale.sigma / scale.scale;
      measured.covariance->covariance +=
          log_sigma * log_sigma * scale.sensitivity * scale.sensitivity.transpose();
    }
    measured.applied_target_scale = scale.scale;
    result = std::move(measured);
  } else if (options.target_scale == TargetScaleMode::kFit) {
    result = CalibrateAtDescribedSize(all_stations, options, selection);
  }
  if (std::string warning = TargetScaleWarning(scale, apply); !warning.empty()) {
    result.warnings.push_back(std::move(warning));
  }
  result.target_scale = scale;
  CertifyResult(ScaleCameraTranslations(handeye::SubProblem(all_stations, selection.used),
                                        result.applied_target_scale),
                &result);
  return result;
}

}  // namespace hecal::estimation
