// `hecal calibrate` (docs/cli.md):
//   hecal calibrate --robot robot.csv --camera camera.csv --setup eye-in-hand|eye-to-hand|auto
//                   [--method NAME|all] [--robot-sigma MM,DEG] [--camera-sigma MM,DEG]
//                   [--output result.json] [--units m|mm] [--keep-outliers]
//                   [--covariance linear|unscented|montecarlo|information] [--covariance-samples N]
//                   [--seed S] [--threads N]
//   hecal calibrate --images DIR --target target.yaml [--intrinsics camera.yaml]
//                   --robot robot.csv --setup ... [--pixel-sigma PX] [--threads N] ...
// From pose tables (calibrate.cc): pairs stations (by id, else by order); refuses the same poses
// given as robot and camera; checks the conventions (handeye/convention_check.h: a wrong setup, an
// inverted file or a wrong unit is named, never solved; --setup auto picks the setup); rejects
// gross outliers (estimation/station_selection.h, unless --keep-outliers); solves with the chosen
// method(s) on the stations kept; adds the plausibility warnings (estimation/plausibility.h) and
// the readers' notes; prints a readable summary and writes the result file (docs/result-file.md).
// From images (calibrate_images.cc): see RunCalibrateImages below.
// Target-free, globally optimal (calibrate_global.cc): see RunCalibrateGlobal below.
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "cli.h"
#include "hecal/estimation/calibrate.h"
#include "hecal/handeye/problem.h"
#include "hecal/io/pose_table.h"
#include "hecal/report/result_file.h"

namespace hecal::vision {
struct ImageSet;  // hecal/vision/image_set.h (built with the vision layer only)
}  // namespace hecal::vision

namespace hecal::cli {

struct CalibrateFlags {
  std::string robot;
  std::string camera;
  std::string images;       // --images DIR (instead of --camera)
  std::string target;       // --target target.yaml (with --images)
  std::string intrinsics;   // --intrinsics camera.yaml (with --images; estimated when absent)
  std::string pixel_sigma;  // --pixel-sigma PX (with --images; estimated when absent)
  int threads = 0;          // --threads (detection, covariance solves; 0 = every core)
  bool refine_intrinsics = false;  // --refine-intrinsics (with --images)
  std::string setup;
  std::string method{estimation::Info(estimation::CalibrateOptions().method).name};  // the default
  std::string robot_sigma;
  std::string camera_sigma;
  std::string output;
  std::string units = "m";
  bool degrees = false;
  std::string euler;
  bool robot_inverse = false;
  bool camera_inverse = false;
  bool keep_outliers = false;  // --keep-outliers: no outlier rejection
  std::string robust = "none";
  std::string covariance;         // --covariance (empty: the method's default)
  int covariance_samples = 5000;  // --covariance-samples (montecarlo)
  std::uint64_t seed = 1;         // --seed (montecarlo, and the outlier consensus)
  std::string correspondences;    // --correspondences FILE (--method global)
  double epsilon = 2e-4;          // --epsilon RAD: the certificate's requested gap (global)
  double relative_gap = 0.1;      // --relative-gap: or this fraction of the optimum (global)
  int matches_per_motion = 40;    // --matches-per-motion: target corners used per motion (global)
  double reach = 2.0;             // --reach M: |t| of X is searched up to this (global)
  long max_cubes = 20'000'000;    // --max-cubes: the search's budget of cube tests (global)
  std::string features = "sift";  // --features sift|orb (global with --target none)
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

// "MM,DEG" (--robot-sigma, --camera-sigma) → PoseSigma in metres and radians; InputError naming
// `flag` when it is not two numbers (the range is the options' IsValid's).
estimation::PoseSigma ParseSigma(const std::string& flag, const std::string& text);

// `hecal calibrate --images`:
//   1. the image front end of vision/image_set.h: detection, intrinsics (given or estimated),
//      PnP poses with covariances, and the per-image report;
//   2. pairing with the robot rows (docs/targets.md): when every robot row has an id and some id
//      is an image's file stem, by id (each image needs a row; rows without an image are left
//      out with a note); otherwise by sorted file name — one robot row per image file, in order,
//      counting the images where the target was not usable (their rows are left out); ids that
//      name no image (such as the row numbers of `hecal import`) get a note;
//   3. the convention check, then report::CalibrateFromImages (report/image_calibration.h):
//      the pose-level method (--method, ml by default; not `all`), then the joint reprojection
//      refinement over X, Z and the robot poses (and the intrinsics with --refine-intrinsics),
//      returned as the result document;
//   4. the summary, a per-image reprojection table (RMS px, flag), and the result file with
//      "refinement": "reprojection" and an "images" section (intrinsics, pixel sigma, per-image
//      RMS and flags, skipped images and why, the pose-level X and Z). Skipped images are the
//      result's rejected stations.
// Errors (InputError, exit 2, nothing written): those of vision/image_set.h, of the robot file,
// the pairing rules above, --method all, a bad --pixel-sigma, --camera-inverse without --camera,
// --covariance unscented (its input would be every pixel's noise). The covariance is the linear
// one of the reprojection problem (pixel and robot noise), or --covariance montecarlo's
// (estimation/image_monte_carlo.h).
void RunCalibrateImages(const CalibrateFlags& flags, const CalibrateSettings& settings,
                        const Io& io);

// Step 2 above (io::PairRobotWithStations, io/image_pairing.h), its notes printed on io.err:
// one robot pose per image of `set`, in its order. Defined with the vision layer.
std::vector<Pose> RobotPosePerImage(const io::PoseTable& robot, const vision::ImageSet& set,
                                    const std::string& images_dir, const Io& io);

// `hecal calibrate --method global --correspondences FILE --intrinsics camera.yaml --robot
// robot.csv --setup eye-in-hand|eye-to-hand [--pixel-sigma PX] [--epsilon RAD] [--reach M]`
// (docs/global.md): the flags become report::GlobalCalibrationOptions (report/
// global_calibration.h; its IsValid holds the ranges, named here by flag); the matches come
// from report::ReadGlobalMatches (the correspondence file), or with `--images DIR --target
// target.yaml --intrinsics camera.yaml` from the target corners detected in the images
// (vision/image_set.h, vision/corner_matches.h), or with `--target none` from SIFT/ORB matches
// between consecutive station images (vision/feature_matches.h); report::CalibrateGlobal runs
// the job; the summary is printed and report::WriteGlobalResult writes the result file.
// Errors (InputError, exit 2, nothing written): those of the job and its readers, --setup auto,
// --camera, --images with --correspondences, --images without --intrinsics or --target, an
// unknown --features, --seed or --units; DegenerateError when the matches do not determine X.
void RunCalibrateGlobal(const CalibrateFlags& flags, const Io& io);

}  // namespace hecal::cli
