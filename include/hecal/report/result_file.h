// The calibration result file (docs/result-file.md, the contract): JSON, or YAML when the output
// path ends in .yaml / .yml. One object per method; `--method all` writes {"results": [ ... ]},
// where a method that refused the data (e.g. Daniilidis' consistency check) appears as
// {"hecal_version", "setup", "method", "error": "<why>"} so that every method is accounted for.
//
// Units: lengths in the input's unit (`units.length`), angles in radians, except fields whose
// name says _deg. Covariances are right-perturbation, (rx, ry, rz, tx, ty, tz), rad² / rad·unit /
// unit², scaled to the output length unit.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/calibrate.h"
#include "hecal/handeye/problem.h"
#include "hecal/io/units.h"
#include "hecal/pose/camera_model.h"

namespace hecal::report {

// A method of `--method all` that refused the data, with its DegenerateError message.
struct MethodFailure {
  estimation::Method method = estimation::Method::kMl;
  std::string message;
};

// The decimals of the per-point pixel fields of "images.per_image" (docs/result-file.md): 0.01 px
// for a detected point and 0.001 px for a residual, well below a detector's accuracy (~0.05 px)
// and a residual's size, so that a 28-image result with ~50 corners each stays near 100 kB.
inline constexpr int kPointDecimals = 2;
inline constexpr int kResidualDecimals = 3;

// `hecal calibrate --images`: the image level of the result, written as "images" (and
// "refinement": "reprojection"). Per-image vectors follow the used stations, in order.
struct ImageReport {
  std::string intrinsics_source;            // the camera.yaml given, or "estimated from the images"
  pose::CameraModel camera;                 // used by the result: given, estimated or refined
  std::optional<double> intrinsics_rms_px;  // when estimated: calibrateCamera's RMS
  // When refined in the joint problem: 1σ of (fx, fy, cx, cy, k1, k2, p1, p2, k3).
  std::optional<std::array<double, pose::kNumIntrinsics>> intrinsics_sigma;
  double pixel_sigma = 0.0;  // px, given or estimated
  bool pixel_sigma_estimated = false;
  double rms_px = 0.0;  // reprojection RMS over every point at the result
  std::vector<double> image_rms_px;
  std::vector<bool> image_outlier;
  // Optional, per used image (empty: not written): its file in the image folder ("im_00.png",
  // "pose_00/image.png"), its detected points (px) and their residuals π(B P_k) − u_k at the
  // result (px), written rounded to kPointDecimals and kResidualDecimals decimals.
  std::vector<std::string> image_files;
  std::vector<std::vector<Eigen::Vector2d>> image_points_px;
  std::vector<std::vector<Eigen::Vector2d>> image_residuals_px;
  std::vector<std::string> skipped_reasons;  // one per ResultDocument::rejected, same order
  estimation::CalibrationResult pose_level;  // X, Z before the reprojection refinement
  // The target's described size (target.yaml's `square`, `marker` or `size`, metres) for the
  // `target` block: the measured size is the scale times it. Empty / 0 when unknown.
  std::string target_size_key;
  double target_size = 0.0;
};

// `hecal calibrate --streams` (docs/streams.md): how the stations were made from two
// time-stamped streams and the time offset, written as "streams" and "time_offset".
struct StreamReport {
  int robot_samples = 0;
  int camera_samples = 0;
  bool camera_gives_stations = true;  // the camera stream is the sparser one
  double max_gap = 0.0;               // seconds
  double smoothing = 0.0;             // seconds, ± of the denser stream's local regression
  // The denser stream's noise at the stations over its noise per sample (a given sigma of that
  // stream is scaled by it; streams/stream_stations.h SmoothedNoiseFactor).
  double smoothed_noise_factor = 1.0;
  double max_angular_speed = 0.0;  // rad/s
  double max_linear_speed = 0.0;   // m/s
  int max_stations = 0;
  int candidates = 0;
  int dropped_outside = 0;
  int dropped_gap = 0;
  int dropped_fast = 0;
  int thinned = 0;
  // Time offset: a camera sample stamped t was taken at robot-clock time t + offset (seconds).
  double offset = 0.0;
  std::optional<double> offset_sigma;   // when estimated and observable
  bool offset_estimated = false;        // false: given (--time-offset)
  double search_window = 0.0;           // seconds, ± of the coarse search
  std::optional<double> coarse_offset;  // the angular-speed correlation's value, when found
  double coarse_correlation = 0.0;
  int profile_evaluations = 0;
  // Cov((X, Z), offset), (δX, δZ) in metres and radians per second of offset; zero when not
  // estimated.
  Eigen::Matrix<double, 12, 1> covariance_with_XZ = Eigen::Matrix<double, 12, 1>::Zero();
};

struct ResultDocument {
  handeye::Setup setup = handeye::Setup::kEyeInHand;
  io::LengthUnit unit = io::LengthUnit::kMetre;        // output length unit
  std::vector<std::string> station_ids;                // one per station of the problem
  std::vector<int> rejected;                           // indices into station_ids
  std::vector<estimation::CalibrationResult> results;  // one, or one per method for `all`
  bool all_methods = false;                            // write {"results": [...]}
  std::vector<MethodFailure> failures;                 // `all` only: methods that refused
  std::optional<ImageReport> images;                   // `calibrate --images` only
  std::optional<StreamReport> streams;                 // `calibrate --streams` only
};

// The ids of the stations that were used (station_ids without the rejected), in order: the
// stations the residuals and per-image vectors of a result follow.
std::vector<std::string> UsedStationIds(const ResultDocument& document);

enum class ResultFormat { kJson, kYaml };
// By extension: .yaml / .yml → YAML, anything else JSON.
ResultFormat ResultFormatForPath(const std::string& path);

std::string FormatResult(const ResultDocument& document, ResultFormat format);
// Atomic write (never a partial file).
void WriteResult(const std::string& path, const ResultDocument& document);

}  // namespace hecal::report
