// `hecal calibrate --method global` (calibrate.h: RunCalibrateGlobal): binds the flags into
// report::GlobalCalibrationOptions, assembles the matches (report::ReadGlobalMatches from a
// correspondence file; vision's target-corner or feature matchers from images), runs
// report::CalibrateGlobal and prints.
#include "bounds.h"
#include "calibrate.h"
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/io/units.h"
#include "hecal/report/global_calibration.h"
#include "hecal/report/global_text.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <filesystem>

#include "hecal/io/camera_file.h"
#include "hecal/io/image_files.h"
#include "hecal/io/image_pairing.h"
#include "hecal/jobs/image_front_end.h"
#include "hecal/vision/corner_matches.h"
#include "hecal/vision/feature_matches.h"
#include "job_output.h"
#endif

namespace hecal::cli {
namespace {

#if defined(HECAL_HAVE_OPENCV_PEERS)
// Target corners as anonymous matches (vision/corner_matches.h).
report::GlobalMatches MatchesFromTargetImages(const CalibrateFlags& flags,
                                              const io::PoseReadOptions& read,
                                              const report::GlobalCalibrationOptions& options,
                                              const Io& io) {
  const io::PoseTable robot = io::ReadPoseTable(flags.robot, read);
  const jobs::JobCallbacks printing = PrintingCallbacks(io);
  const vision::ImageSet set = jobs::DetectImages(
      {flags.images, flags.target, flags.intrinsics, options.threads, vision::ImageUse::kHandEye},
      "hecal calibrate --method global", printing);
  report::GlobalMatches matches;
  matches.T_base_gripper = jobs::RobotPosePerImage(robot, set, flags.images, printing);
  matches.focal = 0.5 * (set.camera.fx + set.camera.fy);
  for (const vision::CornerMotion& corners :
       vision::MatchTargetCorners(set, options.matches_per_motion)) {
    report::GlobalMotion motion{corners.first,
                                corners.second,
                                set.images[std::size_t(corners.first)].id(),
                                set.images[std::size_t(corners.second)].id(),
                                {}};
    for (std::size_t j = 0; j < corners.ids.size(); ++j) {
      motion.pairs.push_back({corners.first_rays[j], corners.second_rays[j], corners.ids[j]});
    }
    matches.motions.push_back(std::move(motion));
  }
  return matches;
}

// Generic image features as matches (--target none; vision/feature_matches.h).
report::GlobalMatches MatchesFromFeatureImages(const CalibrateFlags& flags,
                                               const io::PoseReadOptions& read,
                                               const report::GlobalCalibrationOptions& options,
                                               vision::FeatureKind kind, const Io& io) {
  const io::PoseTable robot = io::ReadPoseTable(flags.robot, read);
  const pose::CameraModel camera = io::ReadCameraFile(flags.intrinsics).camera;
  const io::StationImages listed = io::ListStationImages(flags.images, "the station images");
  report::GlobalMatches matches;
  matches.T_base_gripper = io::PairRobotWithStations(
      robot, listed.stations, flags.images,
      [&io](const std::string& note) { io.err << "hecal: note: " << note << "\n"; });
  matches.focal = 0.5 * (camera.fx + camera.fy);
  std::vector<std::filesystem::path> paths;
  std::vector<std::string> names;
  for (const io::StationImage& station : listed.stations) {
    paths.push_back(station.path);
    names.push_back(station.path.string());
  }
  vision::FeatureMatchOptions match_options;
  match_options.pixel_sigma = options.pixel_sigma;
  match_options.max_matches = options.matches_per_motion;
  match_options.kind = kind;
  const std::vector<std::vector<vision::FeatureMatch>> features =
      vision::MatchConsecutiveImages(paths, names, camera, match_options, options.threads);
  for (std::size_t k = 0; k < features.size(); ++k) {
    report::GlobalMotion motion{
        int(k), int(k + 1), listed.stations[k].id, listed.stations[k + 1].id, {}};
    for (std::size_t j = 0; j < features[k].size(); ++j) {
      motion.pairs.push_back({features[k][j].first_ray, features[k][j].second_ray, int(j)});
    }
    matches.motions.push_back(std::move(motion));
  }
  io.out << "features: " << listed.stations.size() << " images, " << features.size() << " motions, "
         << (kind == vision::FeatureKind::kOrb ? "ORB" : "SIFT") << " matches per motion:";
  for (const auto& motion : features) io.out << " " << motion.size();
  io.out << "\n";
  return matches;
}
#endif

report::GlobalMatches ReadMatches(const CalibrateFlags& flags, const io::PoseReadOptions& read,
                                  [[maybe_unused]] const report::GlobalCalibrationOptions& options,
                                  [[maybe_unused]] const Io& io) {
  if (!flags.camera.empty()) {
    throw InputError("--camera", 0, "--method global reads point matches, not camera poses",
                     "give the matches with --correspondences FILE, or the images with --images "
                     "DIR --target target.yaml (docs/global.md)");
  }
  if (!flags.images.empty()) {
    if (!flags.correspondences.empty()) {
      throw InputError("--correspondences", 0, "--images and --correspondences were both given",
                       "give the matches from one source: the images' target corners or the file");
    }
    if (flags.target.empty()) {
      throw InputError("--target", 0, "--method global with --images needs --target",
                       "give --target target.yaml to match its corners, or --target none to "
                       "match generic image features (docs/global.md)");
    }
    if (flags.intrinsics.empty()) {
      throw InputError("--intrinsics", 0,
                       "--method global with --images needs the camera's intrinsics (estimating "
                       "them would need a target's geometry)",
                       "give --intrinsics camera.yaml (e.g. calibrated with hecal detect)");
    }
#if defined(HECAL_HAVE_OPENCV_PEERS)
    if (flags.target == "none") {
      return MatchesFromFeatureImages(
          flags, read, options,
          flags.features == "orb" ? vision::FeatureKind::kOrb : vision::FeatureKind::kSift, io);
    }
    return MatchesFromTargetImages(flags, read, options, io);
#else
    throw InputError("--images", 0, "this hecal was built without the vision layer (OpenCV)",
                     "rebuild with -DHECAL_BUILD_VISION=ON, or give --correspondences FILE");
#endif
  }
  if (flags.correspondences.empty()) {
    throw InputError("--correspondences", 0, "--method global needs point matches",
                     "give --correspondences FILE (CSV: first,second,u1,v1,u2,v2; "
                     "docs/global.md), or target images with --images DIR --target target.yaml");
  }
  return report::ReadGlobalMatches(flags.robot, read, flags.correspondences, flags.intrinsics);
}

}  // namespace

void RunCalibrateGlobal(const CalibrateFlags& flags, const Io& io) {
  const auto setup = handeye::ParseSetup(flags.setup);
  if (!setup) {
    throw InputError("--setup", 0, "--method global needs the setup, got '" + flags.setup + "'",
                     "give --setup eye-in-hand or --setup eye-to-hand");
  }
  report::GlobalCalibrationOptions options;
  options.setup = *setup;
  options.epsilon = flags.epsilon;
  options.relative_gap = flags.relative_gap;
  options.reach = flags.reach;
  options.max_cubes = flags.max_cubes;
  options.matches_per_motion = flags.matches_per_motion;
  options.threads = flags.threads;
  if (const std::optional<double> sigma = ParsePixelSigma(flags.pixel_sigma))
    options.pixel_sigma = *sigma;
  if (!flags.robot_sigma.empty())
    options.robot_sigma = ParseSigma("--robot-sigma", flags.robot_sigma);
  RequireValid(options);
  if (flags.features != "sift" && flags.features != "orb") {
    throw InputError("--features", 0, "unknown feature kind '" + flags.features + "'",
                     "give --features sift or --features orb");
  }
  options.seed = flags.seed;
  const io::LengthUnit units = ParseUnitsFlag(flags.units);
  io::PoseReadOptions read;
  read.units = units;
  read.degrees = flags.degrees;
  read.invert = flags.robot_inverse;

  const report::GlobalMatches matches = ReadMatches(flags, read, options, io);
  const report::GlobalCalibrationResult result = report::CalibrateGlobal(matches, options);
  report::PrintGlobalSummary(io.out, result, units);
  if (flags.output.empty()) return;
  report::WriteGlobalResult(flags.output, result);
  io.out << "wrote " << flags.output << "\n";
}

}  // namespace hecal::cli
