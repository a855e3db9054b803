// Calibration from target images as one job: see image_calibration.h.
#include "hecal/jobs/image_calibration.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <numbers>
#include <sstream>

#include "hecal/core/error.h"
#include "hecal/estimation/plausibility.h"
#include "hecal/jobs/pose_calibration.h"

namespace hecal::jobs {
namespace {

// Why station `k` (an index into the used stations) was rejected by the calibration.
std::string OutlierReason(const estimation::ImageCalibrationResult& result, size_t k) {
  const int station = result.result.rejected[k];
  const auto image = std::find(result.image_rejected.begin(), result.image_rejected.end(), station);
  std::ostringstream reason;
  reason << std::setprecision(3);
  if (image != result.image_rejected.end()) {
    reason
        << "outlier: reprojection RMS "
        << result.image_rejected_rms_px[static_cast<size_t>(image - result.image_rejected.begin())]
        << " px, beyond 3 sigma of the pixel noise";
  } else {
    const estimation::StationResidual& r = result.result.rejected_residuals[k];
    reason << "outlier: pose residual " << r.rotation * 180.0 / std::numbers::pi << " deg / "
           << r.translation * 1e3 << " mm, beyond 3 sigma of the other stations";
  }
  return reason.str();
}

}  // namespace

report::ResultDocument CalibrateFromImages(const ImageCalibrationInput& input,
                                           estimation::ImageCalibrationOptions options) {
  const size_t used_count =
      static_cast<size_t>(std::count_if(input.skipped.begin(), input.skipped.end(),
                                        [](const std::string& reason) { return reason.empty(); }));
  if (input.skipped.size() != input.image_ids.size() || used_count != input.stations.size() ||
      (!input.image_files.empty() && input.image_files.size() != input.image_ids.size())) {
    throw InputError("image calibration", 0,
                     std::to_string(input.image_ids.size()) + " images, " +
                         std::to_string(input.skipped.size()) + " skip reasons, " +
                         std::to_string(input.image_files.size()) + " file names and " +
                         std::to_string(input.stations.size()) + " stations for " +
                         std::to_string(used_count) + " used images",
                     "give one skip reason (empty when used) and one file name (or none) per "
                     "image, and one station per used image");
  }
  report::ResultDocument document;
  document.unit = input.unit;
  document.setup = options.setup;
  document.station_ids = input.image_ids;
  std::vector<size_t> station_image;  // the image index of every station
  options.calibrate.station_ids.clear();
  for (size_t i = 0; i < input.image_ids.size(); ++i) {
    if (!input.skipped[i].empty()) continue;
    station_image.push_back(i);
    options.calibrate.station_ids.push_back(input.image_ids[i]);
  }
  estimation::ImageCalibrationResult result =
      estimation::CalibrateFromImages(input.stations, options);

  // Rejected: the images the front end skipped, and the outlier stations, in image order.
  std::map<size_t, std::string> rejected;
  for (size_t i = 0; i < input.skipped.size(); ++i) {
    if (!input.skipped[i].empty()) rejected[i] = input.skipped[i];
  }
  for (size_t k = 0; k < result.result.rejected.size(); ++k) {
    rejected[station_image[static_cast<size_t>(result.result.rejected[k])]] =
        OutlierReason(result, k);
  }
  report::ImageReport report;
  for (const auto& [image, reason] : rejected) {
    document.rejected.push_back(static_cast<int>(image));
    report.skipped_reasons.push_back(reason);
  }

  estimation::PlausibilityInput plausibility;
  plausibility.setup = options.setup;
  plausibility.robot_unit_named = input.robot_unit_named;
  for (const estimation::ImageStation& station : input.stations) {
    plausibility.T_base_gripper.push_back(station.T_base_gripper);
    plausibility.T_camera_target.push_back(station.T_camera_target);
  }
  std::vector<std::string> notes = input.notes;
  for (std::string& warning : estimation::PlausibilityWarnings(plausibility, result.result)) {
    notes.push_back(std::move(warning));
  }
  result.result.warnings.insert(result.result.warnings.begin(), notes.begin(), notes.end());

  report.intrinsics_source = input.intrinsics_source;
  report.target_size_key = input.target_size_key;
  report.target_size = input.target_size;
  report.camera = result.reprojection.camera;
  report.intrinsics_rms_px = input.intrinsics_rms_px;
  if (result.reprojection.intrinsics_covariance) {
    std::array<double, pose::kNumIntrinsics> sigma{};
    for (int k = 0; k < pose::kNumIntrinsics; ++k) {
      sigma[static_cast<size_t>(k)] = std::sqrt((*result.reprojection.intrinsics_covariance)(k, k));
    }
    report.intrinsics_sigma = sigma;
  }
  report.pixel_sigma = result.reprojection.pixel_sigma;
  report.pixel_sigma_estimated = result.reprojection.pixel_sigma_estimated;
  report.rms_px = result.reprojection.rms_px;
  report.image_rms_px = result.reprojection.image_rms_px;
  report.image_outlier = result.reprojection.image_outlier;
  // The used stations (not rejected by the calibration), which the per-image vectors follow.
  const std::vector<int>& calibration_rejected = result.result.rejected;
  for (size_t s = 0, k = 0; s < input.stations.size(); ++s) {
    if (std::find(calibration_rejected.begin(), calibration_rejected.end(), static_cast<int>(s)) !=
        calibration_rejected.end())
      continue;
    if (!input.image_files.empty())
      report.image_files.push_back(input.image_files[station_image[s]]);
    report.image_points_px.push_back(input.stations[s].points.pixels);
    report.image_residuals_px.push_back(result.reprojection.residuals_px.at(k++));
  }
  report.pose_level = result.pose_level;
  CheckFiniteResult(result.result);
  document.results.push_back(std::move(result.result));
  document.images = std::move(report);
  return document;
}

}  // namespace hecal::jobs
