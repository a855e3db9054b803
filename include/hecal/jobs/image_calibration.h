// Calibration from target images as one job (`hecal calibrate --images DIR`, docs/architecture.md
// "The data flow of hecal calibrate", from images), beside CalibrateFromPoses
// (pose_calibration.h): the images the front end used (vision/image_set.h; one
// estimation::ImageStation each, paired with its robot pose) go through
// estimation::CalibrateFromImages (the pose level, then the joint reprojection refinement,
// estimation/image_calibration.h), and the result becomes the ResultDocument that
// report::WriteResult writes with its "images" section (docs/result-file.md):
//  - every image is a station of the document (station_ids), in the folder's order;
//  - rejected: the images the front end skipped (with its reason), the pose-level outliers
//    ("outlier: pose residual R deg / T mm, beyond 3 sigma of the other stations") and the
//    image-level outliers ("outlier: reprojection RMS E px, beyond 3 sigma of the pixel
//    noise"), in image order, one reason each (ImageReport::skipped_reasons);
//  - the result's warnings: the caller's notes, then the plausibility warnings
//    (estimation/plausibility.h, on the used stations' poses);
//  - ImageReport: the intrinsics used (given, estimated or refined with their 1σ), the pixel σ,
//    the reprojection RMS over every point and per image, the image outliers and the pose-level
//    result before the refinement; per used image its file (when image_files is given), its
//    detected points and their residuals at the result (the report's per-point figures).
// Frames and units: those of the stations (metres, radians, pixels); `unit` only labels the
// document. `--method all` and the Unscented covariance are refused by the caller (flags).
//
// Errors: InputError when `skipped` (or a non-empty `image_files`) does not have one entry per
// image or the stations do not
// match the used images; those of estimation::CalibrateFromImages (DegenerateError,
// InputError) and CheckFiniteResult pass through.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/image_calibration.h"
#include "hecal/io/units.h"
#include "hecal/report/result_file.h"

namespace hecal::jobs {

struct ImageCalibrationInput {
  io::LengthUnit unit = io::LengthUnit::kMetre;    // the document's output unit (the robot file's)
  bool robot_unit_named = true;                    // false: the robot unit came from a flag
  std::vector<std::string> image_ids;              // every image of the folder, in order
  std::vector<std::string> image_files;            // optional, per image: its file in the folder
  std::vector<std::string> skipped;                // per image: why it is not used, empty when used
  std::vector<estimation::ImageStation> stations;  // one per used image, in order
  std::string intrinsics_source;            // the camera file given, or "estimated from the images"
  std::optional<double> intrinsics_rms_px;  // when estimated: the intrinsics fit's RMS
  std::vector<std::string> notes;           // put first in the result's warnings
  // The target's described size for the result's `target` block: its key in target.yaml
  // ("square", "marker" or "size") and value, metres; empty / 0 when unknown.
  std::string target_size_key;
  double target_size = 0.0;
};

// Runs the job above; options.calibrate.station_ids is set to the used images' ids.
report::ResultDocument CalibrateFromImages(const ImageCalibrationInput& input,
                                           estimation::ImageCalibrationOptions options);

}  // namespace hecal::jobs
