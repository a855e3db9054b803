// `hecal calibrate` (docs/cli.md#hecal-calibrate; the steps:
// docs/architecture.md#the-data-flow-of-hecal-calibrate): the flags of every form, checked once
// (ParseCalibrateFlags), then the form, each a library job with its options bound from the flags:
// from pose tables (calibrate.cc: jobs::CalibrateFromPoseFiles), from images (calibrate_images.cc:
// jobs::CalibrateFromImageFolder) or target-free (calibrate_global.cc: the matches from
// jobs::ReadGlobalMatches or jobs::GlobalMatchesFromImages, then jobs::CalibrateGlobal). These
// files hold the flags, the form dispatch, the checks of flag combinations and the printing only.
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "cli.h"
#include "hecal/hecal.h"

namespace hecal::cli {

struct CalibrateFlags {
  std::string robot;
  std::string camera;
  std::string images;       // --images DIR (instead of --camera)
  std::string target;       // --target target.yaml (with --images)
  std::string intrinsics;   // --intrinsics camera.yaml (with --images; estimated when absent)
  std::string pixel_sigma;  // --pixel-sigma PX (with --images; estimated when absent)
  int threads = 0;          // --threads (detection, covariance solves; 0 = every core)
  bool refine_intrinsics = false;       // --refine-intrinsics (with --images)
  std::optional<handeye::Setup> setup;  // --setup (nullopt: auto)
  std::string method{estimation::Info(estimation::CalibrateOptions().method).name};  // the default
  std::string robot_sigma;
  std::string camera_sigma;
  std::string output;
  std::string report;  // --report: the HTML page (docs/report.md)
  io::LengthUnit units = io::LengthUnit::kMetre;
  bool degrees = false;
  std::optional<EulerSequence> euler;
  bool robot_inverse = false;
  bool camera_inverse = false;
  bool keep_outliers = false;  // --keep-outliers: no outlier rejection
  estimation::RobustLoss robust = estimation::RobustLoss::kNone;
  std::optional<estimation::CovarianceMethod> covariance;  // --covariance (the method's default)
  int covariance_samples = 5000;                           // --covariance-samples (montecarlo)
  std::uint64_t seed = 1;         // --seed (montecarlo, and the outlier consensus)
  std::string correspondences;    // --correspondences FILE (--method global)
  double epsilon = 2e-4;          // --epsilon RAD: the certificate's requested gap (global)
  double relative_gap = 0.1;      // --relative-gap: or this fraction of the optimum (global)
  int matches_per_motion = 40;    // --matches-per-motion: target corners used per motion (global)
  double reach = 2.0;             // --reach M: |t| of X is searched up to this (global)
  long max_cubes = 20'000'000;    // --max-cubes: the search's budget of cube tests (global)
  double time_budget = 120.0;     // --time-budget SECONDS: the search's time (global)
  std::string features = "sift";  // --features sift|orb (global with --target none)
  // --streams: --robot and --camera are time-stamped streams (docs/streams.md).
  bool streams = false;
  std::optional<double> time_offset;  // --time-offset SECONDS: given, not estimated
  double time_offset_window = 1.0;    // --time-offset-window SECONDS
  double max_gap = 0.0;               // --max-gap SECONDS (0: 3 periods of the denser stream)
  std::string max_speed = "300,45";   // --max-speed MM,DEG per second
  int stations = 500;                 // --stations N: at most this many from the streams
  std::string fix;                    // --fix tz=VALUE: planar robots (docs/planar.md)
  std::string stamps;                 // --stamps FILE: with --streams --images (docs/streams.md)
  std::string target_scale = "fit";   // --target-scale fit|stated|VALUE (target-scale.md)
};

// The flags every form shares, checked.
struct CalibrateSettings {
  std::optional<handeye::Setup> setup;   // nullopt: --setup auto
  bool all = false;                      // --method all
  estimation::CalibrateOptions options;  // method (unless all), sigmas, robust loss, covariance
  io::PoseReadOptions read;              // --units, --degrees, --euler (robot and camera files)
};

// Throws InputError naming the flag for a value that does not parse, for options the library
// refuses (estimation::CalibrateOptions::IsValid, its field shown as the flag), when neither or
// both of --camera and --images are given, and for a flag of the --images form (--target,
// --intrinsics, --pixel-sigma, --refine-intrinsics) given with --camera.
CalibrateSettings ParseCalibrateFlags(const CalibrateFlags& flags);

// --pixel-sigma: one finite number of pixels, nullopt when the flag is not given (from images the
// noise is then estimated, for --method global the default applies); the range is the options'
// IsValid's.
std::optional<double> ParsePixelSigma(const std::string& text);

// --fix "tx|ty|tz=VALUE[m|cm|mm]" (planar robots, handeye/planar.h): a component of X's
// translation in X's parent frame, in metres; a VALUE without a unit is in `units` (--units).
// InputError naming --fix when it does not parse, or when its size (above 5 m) says the unit is
// wrong.
handeye::TranslationFix ParseFix(const std::string& text, io::LengthUnit units);

// "MM,DEG" (--robot-sigma, --camera-sigma) → PoseSigma in metres and radians; InputError naming
// `flag` when it is not two numbers (the range is the options' IsValid's).
estimation::PoseSigma ParseSigma(const std::string& flag, const std::string& text);

// --output and --report of the pose and image forms: the result file, and the HTML page
// (jobs::WriteCalibrationReport, with the robot file as read for the 3D scene).
void WriteCalibrateOutputs(const CalibrateFlags& flags, const io::PoseReadOptions& robot_read,
                           const report::ResultDocument& document, const Io& io);

// `hecal calibrate --images`: refuses the flags the image form does not take, binds the others
// into jobs::ImageFolderCalibrationOptions and runs jobs::CalibrateFromImageFolder
// (jobs/image_folder_calibration.h: the image front end, the pairing, the convention check,
// jobs::CalibrateFromImages), printing its texts as they come (job_output.h); then prints the
// summary (report::PrintImageResultSummary) and writes the result.
void RunCalibrateImages(const CalibrateFlags& flags, const CalibrateSettings& settings,
                        const Io& io);

// `hecal calibrate --method global` (docs/global.md): the flags become
// report::GlobalCalibrationOptions (report/global_result.h; its IsValid holds the ranges);
// the flags must name one source of matches (--correspondences, or --images with --target and
// --intrinsics; not --camera), read by jobs::ReadGlobalMatches or jobs::GlobalMatchesFromImages
// (jobs/global_matches.h; --target none and --features choose its MatchSource);
// jobs::CalibrateGlobal runs the job, report::WriteGlobalResult writes the result file.
void RunCalibrateGlobal(const CalibrateFlags& flags, const Io& io);

// The flags of the pose-table forms (--robot, --camera, their reading, setup, method) as the
// pose-file job's options, with the flags' names in its texts.
jobs::PoseFileCalibrationOptions PoseFileOptions(const CalibrateFlags& flags,
                                                 const CalibrateSettings& settings);

// Every result's summary, then the comparison of `--method all`.
void PrintCalibrateSummaries(const report::ResultDocument& document, const Io& io);

// `calibrate --streams` (calibrate_streams.cc): the flags bound into
// jobs::StreamCalibrationOptions (jobs/stream_calibration.h); the job runs, the summaries print,
// the outputs are written.
void RunCalibrateStreams(const CalibrateFlags& flags, const CalibrateSettings& settings,
                         const Io& io);

}  // namespace hecal::cli
