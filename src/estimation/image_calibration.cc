// Hand–eye calibration from images: see image_calibration.h.
#include "hecal/estimation/image_calibration.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "hecal/estimation/image_monte_carlo.h"

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

std::string FlaggedImagesWarning(const ReprojectionResult& reprojection) {
  std::string list;
  int count = 0;
  for (size_t i = 0; i < reprojection.image_outlier.size(); ++i) {
    if (!reprojection.image_outlier[i]) continue;
    char rms[64];
    std::snprintf(rms, sizeof rms, " (%.3f px)", reprojection.image_rms_px[i]);
    list += (count++ == 0 ? "" : ", ") + std::to_string(i + 1) + rms;
  }
  if (count == 0) return {};
  char level[64];
  std::snprintf(level, sizeof level, "%.3f px", 3.0 * reprojection.pixel_sigma);
  return std::string(count == 1 ? "image " : "images ") + list +
         " (counted from 1 among the used images) " + (count == 1 ? "has" : "have") +
         " a reprojection RMS beyond 3 sigma (" + level +
         "): check the detection (blur, glare, a partly hidden target) and the robot pose of " +
         (count == 1 ? "that image" : "those images");
}

}  // namespace

ImageCalibrationResult CalibrateFromImages(const std::vector<ImageStation>& stations,
                                           const ImageCalibrationOptions& options) {
  std::vector<Pose> robot, camera;
  std::vector<ImagePoints> points;
  for (const ImageStation& station : stations) {
    robot.push_back(station.T_base_gripper);
    camera.push_back(station.T_camera_target);
    points.push_back(station.points);
  }
  const handeye::Problem problem = handeye::MakeProblem(options.setup, robot, camera);

  ImageCalibrationResult out;
  CalibrateOptions calibrate = options.calibrate;
  // Step 1 only starts step 2; its covariance is not reported.
  calibrate.covariance.method = CovarianceMethod::kNone;
  if (!calibrate.camera_sigma && !stations.empty()) {
    calibrate.camera_sigma = CameraSigmaFromCovariances(stations);
  }
  out.pose_level = Calibrate(problem, calibrate);

  ReprojectionOptions reprojection;
  reprojection.setup = options.setup;
  reprojection.camera = options.camera;
  reprojection.robot_sigma = out.pose_level.robot_sigma;
  reprojection.pixel_sigma = options.pixel_sigma;
  reprojection.estimate_robot_sigma = !options.calibrate.robot_sigma;
  reprojection.refine_intrinsics = options.refine_intrinsics;
  out.reprojection =
      RefineReprojection(robot, points, out.pose_level.X, out.pose_level.Z, reprojection);

  CalibrationResult& result = out.result;
  result = out.pose_level;
  result.X = out.reprojection.X;
  result.Z = out.reprojection.Z;
  if (options.calibrate.covariance.method == CovarianceMethod::kMonteCarlo) {
    result.covariance = ImageMonteCarloCovariance(robot, points, out.reprojection, reprojection,
                                                  options.calibrate.covariance);
    if (std::string warning = FailedSamplesWarning(*result.covariance); !warning.empty()) {
      result.warnings.push_back(std::move(warning));
    }
  } else {
    CalibrationCovariance covariance;  // the reprojection problem's Gauss–Newton information
    covariance.covariance = out.reprojection.covariance;
    result.covariance = covariance;
  }
  if (out.reprojection.robot_sigma_estimated) {
    result.robot_sigma = out.reprojection.robot_sigma;
    // The pose-level estimate of the robot noise is replaced by the joint one.
    std::erase_if(result.warnings, [](const std::string& warning) {
      return warning.starts_with("robot noise not given");
    });
    char text[160];
    std::snprintf(text, sizeof text,
                  "robot noise not given (--robot-sigma): estimated with the pixel noise from the "
                  "reprojection residuals as %.3g deg, %.3g mm per component",
                  result.robot_sigma.rotation * 180.0 / std::numbers::pi,
                  result.robot_sigma.translation * 1e3);
    result.warnings.insert(result.warnings.begin(), text);
  }
  const NoiseSpec known = NoiseSpec::FromSigmas(result.robot_sigma, result.camera_sigma);
  SetStationResiduals(
      problem,
      EstimateNoise(LinearizeStations(problem, result.X, result.Z), known, LengthScale(problem)),
      &result);
  if (std::string warning = FlaggedImagesWarning(out.reprojection); !warning.empty()) {
    result.warnings.push_back(std::move(warning));
  }
  return out;
}

}  // namespace hecal::estimation
