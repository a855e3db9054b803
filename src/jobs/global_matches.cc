// The matches of the target-free calibration from images: see global_matches.h.
#include "hecal/jobs/global_matches.h"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <utility>
#include <vector>

#include "hecal/core/options_check.h"
#include "hecal/io/camera_file.h"
#include "hecal/io/image_files.h"
#include "hecal/io/image_pairing.h"
#include "hecal/jobs/image_front_end.h"
#include "hecal/vision/corner_matches.h"
#include "hecal/vision/feature_matches.h"

namespace hecal::jobs {
namespace {

// Step 2, kTargetCorners.
GlobalMatches MatchTargetCorners(const GlobalImageMatchOptions& options,
                                         const io::PoseTable& robot,
                                         const JobCallbacks& callbacks) {
  const vision::ImageSet set = DetectImages({options.images, options.target, options.intrinsics,
                                             options.threads, vision::ImageUse::kHandEye},
                                            options.caller, callbacks);
  GlobalMatches matches;
  matches.T_base_gripper = RobotPosePerImage(robot, set, options.images, callbacks);
  matches.focal = 0.5 * (set.camera.fx + set.camera.fy);
  for (const vision::CornerMotion& corners :
       vision::MatchTargetCorners(set, options.matches_per_motion)) {
    GlobalMotion motion{corners.first,
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

// Step 2, kSift and kOrb.
GlobalMatches MatchFeatures(const GlobalImageMatchOptions& options,
                                    const io::PoseTable& robot, const JobCallbacks& callbacks) {
  const pose::CameraModel camera = io::ReadCameraFile(options.intrinsics).camera;
  const io::StationImages listed = io::ListStationImages(options.images, "the station images");
  GlobalMatches matches;
  matches.T_base_gripper =
      io::PairRobotWithStations(robot, listed.stations, options.images,
                                [&callbacks](const std::string& note) { callbacks.Note(note); });
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
  match_options.kind =
      options.source == MatchSource::kOrb ? vision::FeatureKind::kOrb : vision::FeatureKind::kSift;
  const std::vector<std::vector<vision::FeatureMatch>> features =
      vision::MatchConsecutiveImages(paths, names, camera, match_options, options.threads);
  std::ostringstream line;
  line << "features: " << listed.stations.size() << " images, " << features.size() << " motions, "
       << (options.source == MatchSource::kOrb ? "ORB" : "SIFT") << " matches per motion:";
  for (std::size_t k = 0; k < features.size(); ++k) {
    GlobalMotion motion{
        int(k), int(k + 1), listed.stations[k].id, listed.stations[k + 1].id, {}};
    for (std::size_t j = 0; j < features[k].size(); ++j) {
      motion.pairs.push_back({features[k][j].first_ray, features[k][j].second_ray, int(j)});
    }
    matches.motions.push_back(std::move(motion));
    line << " " << features[k].size();
  }
  line << "\n";
  callbacks.Progress(line.str());
  return matches;
}

}  // namespace

bool GlobalImageMatchOptions::IsValid(std::string* why) const {
  if (robot.empty()) {
    return Invalid(why, "GlobalImageMatchOptions.robot", "is empty",
                   "give the robot pose table, one T_base_gripper per image");
  }
  if (!robot_read.IsValid(why)) return false;
  if (images.empty()) {
    return Invalid(why, "GlobalImageMatchOptions.images", "is empty",
                   "give the folder of station images");
  }
  if (intrinsics.empty()) {
    return Invalid(why, "GlobalImageMatchOptions.intrinsics", "is empty",
                   "give the camera file (camera.yaml or ViSP XML): the rays need the intrinsics");
  }
  if (source == MatchSource::kTargetCorners && target.empty()) {
    return Invalid(why, "GlobalImageMatchOptions.target", "is empty",
                   "give the target file whose corners are matched, or match generic features");
  }
  if (!ThreadCountValid(threads, "GlobalImageMatchOptions.threads", why)) return false;
  if (matches_per_motion < 1) {
    return Invalid(why, "GlobalImageMatchOptions.matches_per_motion",
                   "must be at least 1, got " + std::to_string(matches_per_motion), "use e.g. 40");
  }
  if (!(pixel_sigma > 0.0) || !std::isfinite(pixel_sigma)) {
    return Invalid(why, "GlobalImageMatchOptions.pixel_sigma", "must be positive and finite",
                   "give the feature noise per axis in pixels, e.g. 0.5");
  }
  return true;
}

GlobalMatches GlobalMatchesFromImages(const GlobalImageMatchOptions& options,
                                              const JobCallbacks& callbacks) {
  RequireValid(options);
  const io::PoseTable robot = io::ReadPoseTable(options.robot, options.robot_read);
  return options.source == MatchSource::kTargetCorners
             ? MatchTargetCorners(options, robot, callbacks)
             : MatchFeatures(options, robot, callbacks);
}

}  // namespace hecal::jobs
