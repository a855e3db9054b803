#include "field_flags.h"

#include <array>
#include <utility>

namespace hecal::cli {
namespace {

// Options field (the library's InputError source) → the flag that sets it. A field set by no
// flag (CalibrateOptions.robust_scale, TargetSpec.* from a target file) is not listed.
constexpr auto kFieldFlags = std::to_array<std::pair<std::string_view, std::string_view>>({
    {"CalibrateOptions.robot_sigma", "--robot-sigma"},
    {"PivotOptions.sigma", "--robot-sigma"},
    {"PivotFileOptions.robot", "--robot"},
    {"PivotStudyOptions.sigmas", "--sigma"},
    {"PivotStudyOptions.stations", "--stations"},
    {"PivotStudyOptions.trials", "--trials"},
    {"PivotStudyOptions.max_tilt_deg", "--max-tilt"},
    {"CalibrateOptions.camera_sigma", "--camera-sigma"},
    {"CalibrateOptions.fix", "--fix"},
    {"ConventionCheckOptions.setup", "--setup"},
    {"ImageCalibrationOptions.pixel_sigma", "--pixel-sigma"},
    {"ImageFolderCalibrationOptions.robot", "--robot"},
    {"ImageSetOptions.images", "--images"},
    {"ImageSetOptions.target", "--target"},
    {"ImageSetOptions.threads", "--threads"},
    {"MlOptions.robot_sigma", "--robot-sigma"},
    {"MlOptions.camera_sigma", "--camera-sigma"},
    {"CovarianceOptions.method", "--covariance"},
    {"CovarianceOptions.samples", "--covariance-samples"},
    {"CovarianceOptions.threads", "--threads"},
    {"ReprojectionOptions.robot_sigma", "--robot-sigma"},
    {"ReprojectionOptions.pixel_sigma", "--pixel-sigma"},
    {"StudyOptions.settings", "--stations"},
    {"StudyOptions.methods", "--method"},
    {"StudyOptions.trials", "--trials"},
    {"StudyOptions.threads", "--threads"},
    {"Setting.stations", "--stations"},
    {"Setting.gross_outliers", "--outliers"},
    {"Setting.rotation_sigma", "--sigma"},
    {"SimulateOptions.setups", "--setup"},
    {"SimulateOptions.stations", "--stations"},
    {"SimulateOptions.noise_on", "--noise-on"},
    {"SimulateOptions.noise", "--noise"},
    {"SimulateOptions.sigmas", "--sigma"},
    {"SimulateOptions.outliers", "--outliers"},
    {"SimulateOptions.robot_scales", "--robot-scale"},
    {"SimulateOptions.methods", "--method"},
    {"SimulateOptions.trials", "--trials"},
    {"SimulateOptions.threads", "--threads"},
    {"SimulateOptions.covariance_samples", "--covariance-samples"},
    {"BenchOptions.stations", "--stations"},
    {"BenchOptions.methods", "--method"},
    {"BenchOptions.datasets", "--datasets"},
    {"BenchOptions.min_time", "--min-time"},
    {"BenchOptions.sigma", "--sigma"},
    {"PointPoseOptions.focal", "--focal"},
    {"PointPoseOptions.principal_point", "--principal-point"},
    {"PointPoseOptions.pixel_sigma", "--pixel-sigma"},
    {"ImportOptions.format", "--format"},
    {"ImportOptions.units", "--units"},
    {"ImportOptions.setup", "--setup"},
    {"ImportOptions.camera_inverse", "--camera-inverse"},
    {"ContourCamera.focal", "--focal"},
    {"ContourCamera.z0", "--z0"},
    {"ContourStudyOptions.focal_mm", "--focal"},
    {"ContourStudyOptions.z0_mm", "--z0"},
    {"ContourStudyOptions.pixel_size_mm", "--pixel-size"},
    {"ContourStudyOptions.pixel_noise", "--pixel-noise"},
    {"ContourStudyOptions.from", "--from"},
    {"ContourStudyOptions.to", "--to"},
    {"ContourStudyOptions.steps", "--steps"},
    {"ContourStudyOptions.samples", "--samples"},
    {"ContourStudyOptions.threads", "--threads"},
    {"ContourStudyOptions.target", "--contour"},
    {"ContourStudyOptions.unscented", "--ut-w0"},
    {"UnscentedParameters", "--ut-w0"},
    {"UnscentedPoseOptions.unscented", "--ut-w0"},
    {"ShapePoseOptions.shape_covariance", "--covariance"},
    {"RenderOptions.blur_sigma", "--blur"},
    {"RenderOptions.noise_sigma", "--noise"},
    {"EdgeSearchOptions.range", "--search-range"},
    {"ShapeTrackerOptions.measurement_sigma", "--measurement-sigma"},
    {"SequenceRenderOptions.frames", "--frames"},
    {"SequenceRenderOptions.size", "--size"},
    {"SequenceRenderOptions.target", "--contour"},
    {"RefinementOptions.pixel_sigma", "--pixel-sigma"},
    {"PoseConversionOptions.input", "--input"},
    {"FeatureMatchOptions.pixel_sigma", "--pixel-sigma"},
    {"FeatureMatchOptions.max_matches", "--matches-per-motion"},
    {"GlobalCalibrationOptions.epsilon", "--epsilon"},
    {"GlobalCalibrationOptions.relative_gap", "--relative-gap"},
    {"GlobalCalibrationOptions.reach", "--reach"},
    {"GlobalCalibrationOptions.max_cubes", "--max-cubes"},
    {"GlobalCalibrationOptions.time_budget", "--time-budget"},
    {"GlobalCalibrationOptions.matches_per_motion", "--matches-per-motion"},
    {"GlobalCalibrationOptions.threads", "--threads"},
    {"GlobalCalibrationOptions.pixel_sigma", "--pixel-sigma"},
    {"GlobalCalibrationOptions.robot_sigma", "--robot-sigma"},
    {"ImportJobOptions.robot", "--robot"},
    {"ImportJobOptions.camera", "--camera"},
    {"ImportJobOptions.intrinsics", "--intrinsics"},
    {"PoseDetectionOptions.output", "--output"},
    {"PoseFileCalibrationOptions.robot", "--robot"},
    {"PoseFileCalibrationOptions.camera", "--camera"},
    {"GlobalImageMatchOptions.robot", "--robot"},
    {"GlobalImageMatchOptions.images", "--images"},
    {"GlobalImageMatchOptions.target", "--target"},
    {"GlobalImageMatchOptions.intrinsics", "--intrinsics"},
    {"GlobalImageMatchOptions.threads", "--threads"},
    {"GlobalImageMatchOptions.matches_per_motion", "--matches-per-motion"},
    {"GlobalImageMatchOptions.pixel_sigma", "--pixel-sigma"},
    {"ContourTrackingOptions.images", "--images"},
    {"ContourTrackingOptions.init", "--init"},
});

// vision/opencv_pnp.h names the PnP method as "PnpMethod NAME".
constexpr std::string_view kPnpMethod = "PnpMethod ";

}  // namespace

std::optional<std::string_view> FlagForField(std::string_view field) {
  for (const auto& [name, flag] : kFieldFlags) {
    if (name == field) return flag;
  }
  return std::nullopt;
}

InputError WithFlag(const InputError& error) {
  const std::string& source = error.source();
  if (source.starts_with(kPnpMethod)) {
    return InputError("--method " + source.substr(kPnpMethod.size()), error.line(), error.problem(),
                      error.fix());
  }
  if (const std::optional<std::string_view> flag = FlagForField(source)) {
    return InputError(std::string(*flag), error.line(), error.problem(), error.fix());
  }
  return error;
}

}  // namespace hecal::cli
