// Hand–eye calibration from images: see image_calibration.h.
#include "hecal/estimation/image_calibration.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "hecal/core/options_check.h"
#include "hecal/estimation/image_monte_carlo.h"
#include "hecal/estimation/model_check.h"
#include "hecal/estimation/station_selection.h"

namespace hecal::estimation {
namespace {

// RMS over the stations of the PnP poses' per-axis standard deviations.
PoseSigma CameraSigmaFromCovariances(const std::vector<ImageStation>& stations) {
  double rotation = 0.0, translation = 0.0;
  for (const ImageStation& station : stations) {
    rotation += station.camera_covariance.topLeftCorner<3, 3>().trace() / 3.0;
    translation += station.camera_covariance.bottomRightCorner<3, 3>().trace() / 3.0;
  }
  const double n = static_cast<double>(stations.size());
  return {std::sqrt(rotation / n), std::sqrt(translation / n)};
}

// Names for messages: the caller's station ids (of every station), else numbers from 1.
std::string StationName(const CalibrateOptions& options, size_t i) {
  return i < options.station_ids.size() ? options.station_ids[i] : std::to_string(i + 1);
}

std::string Px(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f px", value);
  return text;
}

// `flags` and `rms` follow the used stations (`used_index` maps them to all stations).
std::string FlaggedImagesWarning(const std::vector<bool>& flags, const std::vector<double>& rms,
                                 const std::vector<int>& used_index, double pixel_sigma,
                                 const CalibrateOptions& options, bool rejected) {
  std::string list;
  int count = 0;
  for (size_t k = 0; k < flags.size(); ++k) {
    if (!flags[k]) continue;
    list += (count++ == 0 ? "" : ", ") + StationName(options, static_cast<size_t>(used_index[k])) +
            " (" + Px(rms[k]) + ")";
  }
  if (count == 0) return {};
  return std::string(count == 1 ? "image " : "images ") + list + " " +
         (count == 1 ? "has" : "have") + " a reprojection RMS beyond 3 sigma (" +
         Px(3.0 * pixel_sigma) + ")" +
         (rejected ? std::string(": rejected")
                   : std::string(": still used (more could not be rejected)")) +
         "; check the detection (blur, glare, a partly hidden target) and the robot pose of " +
         (count == 1 ? "that image" : "those images");
}

// The robot noise's effect at the scene, √(σ_t² + (σ_r L)²) (header, step 4).
double SceneEffect(const PoseSigma& sigma, double length_scale) {
  return std::hypot(sigma.translation, sigma.rotation * length_scale);
}

// The largest |log(s_joint / s_pose)| their sampling error allows on `stations` stations,
// 2/√(3n − 6); infinite when there are no degrees of freedom.
double AgreementLimit(size_t stations) {
  const double dof = 3.0 * static_cast<double>(stations) - 6.0;
  return dof > 0.0 ? 2.0 / std::sqrt(dof) : std::numeric_limits<double>::infinity();
}

std::string Sigma(const PoseSigma& sigma) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g deg, %.3g mm", sigma.rotation * 180.0 / std::numbers::pi,
                sigma.translation * 1e3);
  return text;
}

}  // namespace

bool CovarianceTakesPoseLevelRobotNoise(const PoseSigma& joint, const PoseSigma& pose_level,
                                        size_t stations, double length_scale) {
  const double a = SceneEffect(joint, length_scale), b = SceneEffect(pose_level, length_scale);
  if (!(b > a)) return false;
  return stations < kModelCheckMinStations || !(a > 0.0) ||
         std::log(b / a) > AgreementLimit(stations);
}

std::string RobotNoiseAgreementWarning(const PoseSigma& joint, const PoseSigma& pose_level,
                                       size_t stations, double length_scale,
                                       const std::string& largest, double largest_deg) {
  const double limit = AgreementLimit(stations);
  const double a = SceneEffect(joint, length_scale), b = SceneEffect(pose_level, length_scale);
  if (!(a > 0.0 && b > 0.0) || std::abs(std::log(a / b)) <= limit) return {};
  const double deg = 180.0 / std::numbers::pi;
  char text[760];
  std::snprintf(
      text, sizeof text,
      "the robot noise estimated from the images (%.3g deg, %.3g mm: %.3g mm at %.3g m) "
      "disagrees with what the pose-level residuals imply (%.3g deg, %.3g mm: %.3g mm) by a "
      "factor %.2f, beyond their sampling error (%.2f with %zu stations); the covariance of X "
      "rests on the larger, %s estimate. Likely cause: %s; the largest pose-level residual is "
      "station "
      "%s (%.3g deg) (fix: check that station's robot pose and image, or give --robot-sigma)",
      joint.rotation * deg, joint.translation * 1e3, a * 1e3, length_scale,
      pose_level.rotation * deg, pose_level.translation * 1e3, b * 1e3, std::max(a / b, b / a),
      std::exp(limit), stations, a < b ? "pose-level" : "image",
      a < b ? "a few stations dominate the pose-level residuals (a robot pose off by more than "
              "the noise is absorbed into that station's free robot pose, and the estimate "
              "collapses toward zero with the covariance)"
            : "the pose-level camera noise (an isotropic summary of the PnP covariances) is "
              "wrong, or the pixels are noisier than the robot poses explain",
      largest.c_str(), largest_deg);
  return text;
}

bool ImageCalibrationOptions::IsValid(std::string* why) const {
  return PixelSigmaIsValid(pixel_sigma, "ImageCalibrationOptions.pixel_sigma", why) &&
         calibrate.IsValid(why);
}

ImageCalibrationResult CalibrateFromImages(const std::vector<ImageStation>& stations,
                                           const ImageCalibrationOptions& options) {
  RequireValid(options);
  std::vector<Pose> robot, camera;
  for (const ImageStation& station : stations) {
    robot.push_back(station.T_base_gripper);
    camera.push_back(station.T_camera_target);
  }
  const handeye::Problem problem = handeye::MakeProblem(options.setup, robot, camera);
  const size_t n = stations.size();

  ImageCalibrationResult out;
  CalibrateOptions calibrate = options.calibrate;
  // Step 1 only starts step 2; its covariance is not reported.
  calibrate.covariance.method = CovarianceMethod::kNone;
  if (!calibrate.camera_sigma && !stations.empty()) {
    calibrate.camera_sigma = CameraSigmaFromCovariances(stations);
  }
  // The pose-level camera sigma above is a crude summary of the PnP covariances (isotropic, the
  // same for every image), so the outlier test at that level uses each image's own PnP
  // covariance (station_selection.h): it rejects stations that disagree with the others, not
  // stations whose PnP pose is merely less precise than the average.
  StationSelection selection = AllStations(n);
  if (calibrate.reject_outliers) {
    StationSelectionOptions selection_options;
    selection_options.robot_sigma = options.calibrate.robot_sigma;
    selection_options.camera_sigma = calibrate.camera_sigma;
    for (const ImageStation& station : stations)
      selection_options.camera_covariances.push_back(station.camera_covariance);
    selection_options.consensus = calibrate.consensus;
    selection = SelectStations(problem, selection_options);
  }
  out.pose_level = Calibrate(problem, calibrate, selection);
  // The target's scale (target_scale.h): when the pose level answers at a measured (or given)
  // size, the image level takes the same size — every target point scaled by it — and its
  // covariance gains the scale's share below (docs/target-scale.md).
  // With --refine-intrinsics the pose level's scale shares the given focal length's error (a
  // focal length 1 % off puts every PnP camera 1 % too far, as a board printed at 101 % would),
  // which the image level then corrects: there the described size is kept, not the pose level's
  // fitted one (a given scale is still applied).
  const bool scale_confounded =
      options.refine_intrinsics && options.calibrate.target_scale == TargetScaleMode::kFit;
  const double target_scale = scale_confounded ? 1.0 : out.pose_level.applied_target_scale;
  const handeye::Problem measured_problem = ScaleCameraTranslations(problem, target_scale);
  std::vector<ImagePoints> points;
  for (const ImageStation& station : stations) {
    points.push_back(station.points);
    for (Eigen::Vector3d& P : points.back().target) P *= target_scale;
  }

  ReprojectionOptions reprojection;
  reprojection.setup = options.setup;
  reprojection.camera = options.camera;
  reprojection.robot_sigma = out.pose_level.robot_sigma;
  reprojection.pixel_sigma = options.pixel_sigma;
  reprojection.estimate_robot_sigma = !options.calibrate.robot_sigma;
  reprojection.refine_intrinsics = options.refine_intrinsics;

  // Step 2 on the stations step 1 kept; an image whose reprojection RMS is beyond 3σ_px is
  // rejected and step 2 repeated (at most ⌊(n − 3)/2⌋ stations rejected in all).
  std::vector<bool> used(n, true);
  for (int i : out.pose_level.rejected) used[static_cast<size_t>(i)] = false;
  const size_t max_rejected = n >= 3 ? (n - 3) / 2 : 0;
  Pose X0 = out.pose_level.X, Z0 = out.pose_level.Z;
  std::vector<std::string> image_warnings;
  while (true) {
    const std::vector<int> used_index = TrueIndices(used);
    std::vector<Pose> used_robot;
    std::vector<ImagePoints> used_points;
    for (int i : used_index) {
      used_robot.push_back(robot[static_cast<size_t>(i)]);
      used_points.push_back(points[static_cast<size_t>(i)]);
    }
    out.reprojection = RefineReprojection(used_robot, used_points, X0, Z0, reprojection);
    const std::vector<int> flagged = TrueIndices(out.reprojection.image_outlier);
    if (flagged.empty()) break;
    const size_t rejected = static_cast<size_t>(std::count(used.begin(), used.end(), false));
    const bool reject = rejected + flagged.size() <= max_rejected;
    image_warnings.push_back(
        FlaggedImagesWarning(out.reprojection.image_outlier, out.reprojection.image_rms_px,
                             used_index, out.reprojection.pixel_sigma, options.calibrate, reject));
    if (!reject) break;
    for (int k : flagged) {
      const int i = used_index[static_cast<size_t>(k)];
      used[static_cast<size_t>(i)] = false;
      out.image_rejected.push_back(i);
      out.image_rejected_rms_px.push_back(out.reprojection.image_rms_px[static_cast<size_t>(k)]);
    }
    X0 = out.reprojection.X;
    Z0 = out.reprojection.Z;
  }
  std::vector<Pose> used_robot;
  std::vector<ImagePoints> used_points;
  for (int i : TrueIndices(used)) {
    used_robot.push_back(robot[static_cast<size_t>(i)]);
    used_points.push_back(points[static_cast<size_t>(i)]);
  }
  const handeye::Problem used_problem = handeye::SubProblem(measured_problem, used);
  const double length_scale = handeye::LengthScale(used_problem);

  // Step 5 (header): the robot noise the covariance rests on.
  ReprojectionResult for_covariance = out.reprojection;
  const PoseSigma& joint = out.reprojection.robot_sigma_covariance;
  const PoseSigma& pose_level = out.pose_level.robot_sigma;
  const PoseSigma larger{std::max(pose_level.rotation, joint.rotation),
                         std::max(pose_level.translation, joint.translation)};
  const bool take_pose_level =
      out.reprojection.robot_sigma_estimated &&
      CovarianceTakesPoseLevelRobotNoise(out.reprojection.robot_sigma, pose_level,
                                         used_robot.size(), length_scale) &&
      (larger.rotation > joint.rotation || larger.translation > joint.translation);
  if (take_pose_level) {
    ReprojectionOptions fixed = reprojection;
    fixed.robot_sigma = larger;
    fixed.estimate_robot_sigma = false;
    fixed.pixel_sigma = out.reprojection.pixel_sigma;
    if (options.refine_intrinsics) fixed.camera = out.reprojection.camera;
    for_covariance.covariance =
        RefineReprojection(used_robot, used_points, out.reprojection.X, out.reprojection.Z, fixed)
            .covariance;
    for_covariance.robot_sigma = fixed.robot_sigma;
    for_covariance.robot_sigma_covariance = fixed.robot_sigma;
  }

  CalibrationResult& result = out.result;
  result = out.pose_level;
  result.applied_target_scale = target_scale;
  if (scale_confounded && result.target_scale && result.target_scale->Mismatch()) {
    result.warnings.push_back(
        "with --refine-intrinsics the target's size measured at the pose level shares the given "
        "focal length's error, so X and Z are given at the described size: calibrate once "
        "without --refine-intrinsics, or measure the printed target (docs/target-scale.md)");
  }
  result.X = out.reprojection.X;
  result.Z = out.reprojection.Z;
  if (options.calibrate.covariance.method == CovarianceMethod::kMonteCarlo) {
    result.covariance = ImageMonteCarloCovariance(used_robot, used_points, for_covariance,
                                                  reprojection, options.calibrate.covariance);
    result.seed = options.calibrate.covariance.seed;
    if (std::string warning = FailedSamplesWarning(*result.covariance); !warning.empty()) {
      result.warnings.push_back(std::move(warning));
    }
  } else {
    CalibrationCovariance covariance;  // the reprojection problem's Gauss–Newton information
    covariance.covariance = for_covariance.covariance;
    result.covariance = covariance;
  }
  if (result.target_scale && target_scale != 1.0) {
    // A measured scale's share, Cov(δ | s) + g σ_ε² gᵀ, g from the pose level.
    const double log_sigma = result.target_scale->sigma / result.target_scale->scale;
    result.covariance->covariance += log_sigma * log_sigma * result.target_scale->sensitivity *
                                     result.target_scale->sensitivity.transpose();
  }
  if (out.reprojection.robot_sigma_estimated) {
    result.robot_sigma = out.reprojection.robot_sigma;
    // The pose-level estimate of the robot noise is replaced by the joint one.
    std::erase_if(result.warnings, [](const std::string& warning) {
      return warning.starts_with("robot noise not given");
    });
    result.warnings.insert(result.warnings.begin(),
                           "robot noise not given (--robot-sigma): estimated with the pixel noise "
                           "from the reprojection residuals as " +
                               Sigma(result.robot_sigma) + " per component");
  }
  if (take_pose_level) {
    result.robot_sigma = for_covariance.robot_sigma;
    if (used_robot.size() < kModelCheckMinStations) {
      result.warnings.push_back(
          "with " + std::to_string(used_robot.size()) +
          " stations no check of the noise model is possible (it needs at least " +
          std::to_string(kModelCheckMinStations) +
          "): the covariance of X takes the larger of the two robot-noise estimates, " +
          Sigma(result.robot_sigma) + " per component (from the images " +
          Sigma(out.reprojection.robot_sigma) + ", from the pose-level residuals " +
          Sigma(out.pose_level.robot_sigma) + ") (fix: add stations, or give --robot-sigma)");
    }
  }
  const NoiseSpec known = NoiseSpec::FromSigmas(result.robot_sigma, result.camera_sigma);
  const NoiseEstimate noise =
      EstimateNoise(LinearizeStations(used_problem, result.X, result.Z), known, length_scale);
  SetStationResiduals(used_problem, noise, &result);
  // The certificate of the image level's X, Z (the pose level's is replaced).
  result.global_optimum.reset();
  std::erase_if(result.warnings, [](const std::string& warning) {
    return warning.starts_with("the answer is not the global optimum") ||
           warning.starts_with("the answer could not be certified");
  });
  CertifyResult(used_problem, &result);
  if (out.reprojection.robot_sigma_estimated) {
    const std::vector<int> used_index = TrueIndices(used);
    size_t largest = 0;
    for (size_t k = 0; k < result.residuals.size(); ++k)
      if (result.residuals[k].rotation > result.residuals[largest].rotation) largest = k;
    if (!result.residuals.empty()) {
      if (std::string warning = RobotNoiseAgreementWarning(
              out.reprojection.robot_sigma, out.pose_level.robot_sigma, used_index.size(),
              length_scale,
              StationName(options.calibrate, static_cast<size_t>(used_index[largest])),
              result.residuals[largest].rotation * 180.0 / std::numbers::pi);
          !warning.empty()) {
        result.warnings.push_back(std::move(warning));
      }
    }
  }
  result.rejected.clear();
  for (size_t i = 0; i < n; ++i)
    if (!used[i]) result.rejected.push_back(static_cast<int>(i));
  result.rejected_residuals =
      RejectedResiduals(measured_problem, used, result.X, result.Z, noise.variances);
  result.rejected_ids.clear();
  for (int i : result.rejected) {
    if (static_cast<size_t>(i) < options.calibrate.station_ids.size())
      result.rejected_ids.push_back(options.calibrate.station_ids[static_cast<size_t>(i)]);
  }
  for (std::string& warning : image_warnings) result.warnings.push_back(std::move(warning));
  return out;
}

}  // namespace hecal::estimation
