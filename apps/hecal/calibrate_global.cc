// `hecal calibrate --method global` (calibrate.h: RunCalibrateGlobal).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bounds.h"
#include "calibrate.h"
#include "hecal/core/error.h"
#include "hecal/estimation/epipolar_polish.h"
#include "hecal/estimation/epipolar_robot_noise.h"
#include "hecal/geometry/so3.h"
#include "hecal/global/outlier_removal.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/camera_file.h"
#include "hecal/io/correspondence_file.h"
#include "hecal/io/units.h"
#include "hecal/report/json_matrix.h"

#if defined(HECAL_HAVE_OPENCV_PEERS)
#include <filesystem>

#include "hecal/io/image_files.h"
#include "hecal/io/image_pairing.h"
#include "hecal/vision/feature_matches.h"
#include "image_report.h"
#endif

namespace hecal::cli {
namespace {

struct GlobalInput {
  global::EpipolarProblem problem;
  std::vector<std::pair<std::string, std::string>> motion_names;
  double focal = 1.0;  // pixels (1 for bearings)
};

// The unit ray of a pixel through the camera (undistorted with its plumb_bob model).
Eigen::Vector3d PixelRay(const pose::CameraModel& camera, const Eigen::Vector2d& pixel,
                         const std::string& source, int line) {
  const auto normalised = pose::Undistort(camera, pixel);
  if (!normalised) {
    throw InputError(source, line,
                     "pixel (" + std::to_string(pixel.x()) + ", " + std::to_string(pixel.y()) +
                         ") cannot be undistorted",
                     "check the pixel against the image size and the intrinsics");
  }
  return Eigen::Vector3d(normalised->x(), normalised->y(), 1.0).normalized();
}

io::PoseTable ReadRobot(const CalibrateFlags& flags) {
  const auto units = io::ParseLengthUnit(flags.units);
  if (!units) throw InputError("--units", 0, "unknown unit '" + flags.units + "'", "use m or mm");
  io::PoseReadOptions read;
  read.units = *units;
  read.degrees = flags.degrees;
  read.invert = flags.robot_inverse;
  return io::ReadPoseTable(flags.robot, read);
}

GlobalInput MatchesFromFile(const CalibrateFlags& flags, handeye::Setup setup) {
  const io::PoseTable robot = ReadRobot(flags);
  const io::CorrespondenceFile matches = io::ReadCorrespondenceFile(flags.correspondences);
  std::optional<pose::CameraModel> camera;
  if (matches.pixels) {
    if (flags.intrinsics.empty()) {
      throw InputError("--intrinsics", 0, flags.correspondences + " gives pixels",
                       "give the camera with --intrinsics camera.yaml, or write bearings "
                       "(x1,y1,z1,x2,y2,z2)");
    }
    camera = io::ReadCameraFile(flags.intrinsics).camera;
  }
  // Stations: by id when every robot row has one, else by 1-based row number.
  const bool by_id = std::all_of(robot.rows.begin(), robot.rows.end(),
                                 [](const io::PoseRow& row) { return row.id.has_value(); });
  std::map<std::string, int> station;
  for (std::size_t i = 0; i < robot.rows.size(); ++i) {
    station[by_id ? *robot.rows[i].id : std::to_string(i + 1)] = int(i);
  }
  GlobalInput input;
  input.problem.setup = setup;
  input.focal = camera ? 0.5 * (camera->fx + camera->fy) : 1.0;
  for (const io::CorrespondenceMotion& motion : matches.motions) {
    for (const std::string& name : {motion.first, motion.second}) {
      if (!station.count(name)) {
        throw InputError(flags.correspondences, motion.line,
                         "station '" + name + "' is not in " + flags.robot,
                         by_id ? "use the robot file's id column values"
                               : "number stations by the robot file's rows, from 1");
      }
    }
    global::EpipolarMotion out;
    out.first_station = station[motion.first];
    out.second_station = station[motion.second];
    out.hand = global::HandPose(setup, robot.rows[out.first_station].pose).inverse() *
               global::HandPose(setup, robot.rows[out.second_station].pose);
    for (std::size_t k = 0; k < motion.ids.size(); ++k) {
      Eigen::Vector3d rays[2] = {motion.first_points[k], motion.second_points[k]};
      if (camera) {
        for (Eigen::Vector3d& ray : rays) {
          ray = PixelRay(*camera, ray.head<2>(), flags.correspondences, motion.lines[k]);
        }
      }
      out.pairs.push_back({rays[0], rays[1], motion.ids[k]});
    }
    input.problem.motions.push_back(std::move(out));
    input.motion_names.emplace_back(motion.first, motion.second);
  }
  return input;
}

#if defined(HECAL_HAVE_OPENCV_PEERS)
// Target corners as anonymous matches: the corners the detector finds in the images of two
// consecutive usable stations (sorted by file name) with the same id are one match of that
// motion. Only the ids and pixels are used; the target's size and square never enter X. At
// most `per_motion` matches per motion, evenly spaced in id order (spread over the target).
GlobalInput MatchesFromTargetImages(const CalibrateFlags& flags, handeye::Setup setup, int threads,
                                    int per_motion, const Io& io) {
  const io::PoseTable robot = ReadRobot(flags);
  const ImageSet set =
      DetectImageSet({flags.images, flags.target, flags.intrinsics, threads, ImageUse::kHandEye},
                     "hecal calibrate --method global", io);
  const std::vector<Pose> robot_poses = RobotPosePerImage(robot, set, flags.images, io);
  std::vector<int> used;
  for (std::size_t i = 0; i < set.images.size(); ++i) {
    if (set.images[i].used()) used.push_back(int(i));
  }
  GlobalInput input;
  input.problem.setup = setup;
  input.focal = 0.5 * (set.camera.fx + set.camera.fy);
  for (std::size_t k = 0; k + 1 < used.size(); ++k) {
    const ImageRecord& first = set.images[used[k]];
    const ImageRecord& second = set.images[used[k + 1]];
    // Both point lists are sorted by id.
    std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> common;
    std::vector<int> ids;
    auto a = first.detection.points.begin(), b = second.detection.points.begin();
    while (a != first.detection.points.end() && b != second.detection.points.end()) {
      if (a->id < b->id) {
        ++a;
      } else if (b->id < a->id) {
        ++b;
      } else {
        common.emplace_back(a->pixel, b->pixel);
        ids.push_back(a->id);
        ++a;
        ++b;
      }
    }
    global::EpipolarMotion motion;
    motion.first_station = used[k];
    motion.second_station = used[k + 1];
    motion.hand = global::HandPose(setup, robot_poses[used[k]]).inverse() *
                  global::HandPose(setup, robot_poses[used[k + 1]]);
    const int n = int(common.size());
    const int take = std::min(n, per_motion);
    for (int j = 0; j < take; ++j) {
      const int index = int((long(j) * n) / take);
      motion.pairs.push_back({PixelRay(set.camera, common[index].first, first.name, 0),
                              PixelRay(set.camera, common[index].second, second.name, 0),
                              ids[index]});
    }
    input.problem.motions.push_back(std::move(motion));
    input.motion_names.emplace_back(first.id(), second.id());
  }
  return input;
}

// Generic image features as matches (--target none): SIFT matches between the images of
// consecutive stations (sorted by name), checked by an essential-matrix RANSAC
// (vision/feature_matches.h), at most `per_motion` per motion spread over the image.
GlobalInput MatchesFromFeatureImages(const CalibrateFlags& flags, handeye::Setup setup, int threads,
                                     int per_motion, double pixel_sigma, const Io& io) {
  const io::PoseTable robot = ReadRobot(flags);
  const pose::CameraModel camera = io::ReadCameraFile(flags.intrinsics).camera;
  const io::StationImages listed = io::ListStationImages(flags.images, "the station images");
  const std::vector<Pose> robot_poses = io::PairRobotWithStations(
      robot, listed.stations, flags.images,
      [&io](const std::string& note) { io.err << "hecal: note: " << note << "\n"; });
  std::vector<std::filesystem::path> paths;
  std::vector<std::string> names;
  for (const io::StationImage& station : listed.stations) {
    paths.push_back(station.path);
    names.push_back(station.path.string());
  }
  vision::FeatureMatchOptions options;
  options.pixel_sigma = pixel_sigma;
  options.max_matches = per_motion;
  options.kind = flags.features == "orb" ? vision::FeatureKind::kOrb : vision::FeatureKind::kSift;
  const std::vector<std::vector<vision::FeatureMatch>> matches =
      vision::MatchConsecutiveImages(paths, names, camera, options, threads);
  GlobalInput input;
  input.problem.setup = setup;
  input.focal = 0.5 * (camera.fx + camera.fy);
  for (std::size_t k = 0; k < matches.size(); ++k) {
    global::EpipolarMotion motion;
    motion.first_station = int(k);
    motion.second_station = int(k + 1);
    motion.hand = global::HandPose(setup, robot_poses[k]).inverse() *
                  global::HandPose(setup, robot_poses[k + 1]);
    for (std::size_t j = 0; j < matches[k].size(); ++j) {
      motion.pairs.push_back({matches[k][j].first_ray, matches[k][j].second_ray, int(j)});
    }
    input.problem.motions.push_back(std::move(motion));
    input.motion_names.emplace_back(listed.stations[k].id, listed.stations[k + 1].id);
  }
  io.out << "features: " << listed.stations.size() << " images, " << matches.size() << " motions, "
         << (flags.features == "orb" ? "ORB" : "SIFT") << " matches per motion:";
  for (const auto& motion : matches) io.out << " " << motion.size();
  io.out << "\n";
  return input;
}
#endif

GlobalInput ReadGlobalInput(const CalibrateFlags& flags, handeye::Setup setup,
                            [[maybe_unused]] int threads, [[maybe_unused]] double pixel_sigma,
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
      return MatchesFromFeatureImages(flags, setup, threads, flags.matches_per_motion, pixel_sigma,
                                      io);
    }
    return MatchesFromTargetImages(flags, setup, threads, flags.matches_per_motion, io);
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
  return MatchesFromFile(flags, setup);
}

}  // namespace

void RunCalibrateGlobal(const CalibrateFlags& flags, const Io& io) {
  const auto setup = handeye::ParseSetup(flags.setup);
  if (!setup) {
    throw InputError("--setup", 0, "--method global needs the setup, got '" + flags.setup + "'",
                     "give --setup eye-in-hand or --setup eye-to-hand");
  }
  if (!(flags.epsilon > 0.0 && flags.epsilon <= 1.0)) {
    throw InputError("--epsilon", 0, "must be above 0 and at most 1 rad",
                     "give the certificate's gap in radians, e.g. 2e-4");
  }
  if (!(flags.matches_per_motion >= 8 && flags.matches_per_motion <= 100000)) {
    throw InputError("--matches-per-motion", 0, "must be at least 8 and at most 100000",
                     "give how many matches per motion the search uses, e.g. 40");
  }
  if (!(flags.relative_gap >= 0.0 && flags.relative_gap < 1.0)) {
    throw InputError("--relative-gap", 0, "must be at least 0 and below 1",
                     "give the certificate's gap as a fraction of the optimum, e.g. 0.1 (0: "
                     "only --epsilon)");
  }
  if (!(flags.reach > 0.0 && flags.reach <= 1000.0)) {
    throw InputError("--reach", 0, "must be above 0 and at most 1000 m",
                     "give the largest camera offset from the hand in metres, e.g. 2");
  }
  if (!(flags.max_cubes >= 1)) {
    throw InputError("--max-cubes", 0, "must be at least 1",
                     "give the search's budget of cube tests, e.g. 1000000");
  }
  if (flags.features != "sift" && flags.features != "orb") {
    throw InputError("--features", 0, "unknown feature kind '" + flags.features + "'",
                     "give --features sift or --features orb");
  }
  const int threads = CheckThreads("--threads", flags.threads);
  const std::uint64_t seed = flags.seed;
  double pixel_sigma = 0.5;
  if (!flags.pixel_sigma.empty()) {
    std::istringstream in(flags.pixel_sigma);
    if (!(in >> pixel_sigma) || !std::isfinite(pixel_sigma)) {
      throw InputError("--pixel-sigma", 0, "'" + flags.pixel_sigma + "' is not a number",
                       "give the pixel noise per axis in pixels, e.g. 0.5");
    }
    CheckPixelSigma("--pixel-sigma", pixel_sigma);
  }
  const GlobalInput input = ReadGlobalInput(flags, *setup, threads, pixel_sigma, io);
  global::SearchOptions search;
  search.epsilon = flags.epsilon;
  search.relative_gap = flags.relative_gap;
  search.translation_bound = flags.reach;
  search.max_cubes = flags.max_cubes;
  search.threads = threads;
  global::OutlierOptions outliers;
  outliers.threshold = 4.0 * std::sqrt(2.0) * pixel_sigma / input.focal;
  outliers.seed = seed;
  const global::RobustGlobalSolution robust =
      global::SolveGlobalRobust(input.problem, search, outliers);
  const estimation::RecheckedPolish rechecked =
      estimation::PolishAndRecheck(input.problem, robust.inliers, robust.solution.X);
  // The final X and covariance with the robot's pose error marginalised (the re-check above
  // treats pairs as independent, which only decides which pairs to keep).
  const estimation::RobotNoisePolish robot_noise =
      estimation::PolishWithEstimatedRobotNoise(rechecked.inliers, rechecked.polish.X, flags.reach);
  const estimation::EpipolarPolish& polish = robot_noise.polish;
  // The stage that removed each pair the re-check leaves out (pairs it re-admits are not listed).
  std::map<std::pair<int, int>, std::string> stage;
  for (const global::RemovedPair& r : robust.removed) {
    stage[{r.motion, r.id}] = r.by_prefilter ? "epipolar ransac" : "l-infinity support set";
  }
  const global::Certificate& c = robust.solution.certificate;

  const double metres = io::MetresPer(*io::ParseLengthUnit(flags.units));
  const Pose& X = polish.X;
  const Vector6d sd = polish.covariance.diagonal().cwiseSqrt();
  io.out << "method global (" << handeye::SetupName(*setup) << ", target-free)\n"
         << handeye::XFrameName(*setup) << ": rotation vector [rad] "
         << so3::Log(X.linear()).transpose() << ", translation [" << flags.units << "] "
         << (X.translation() / metres).transpose() << "\n"
         << "  1 sigma: rotation [rad] " << sd.head<3>().transpose() << ", translation ["
         << flags.units << "] " << (sd.tail<3>() / metres).transpose() << "\n"
         << "  noise (estimated): ray [rad] " << robot_noise.noise.ray_sigma
         << ", robot per pose: rotation [rad] " << robot_noise.noise.robot_rotation_sigma
         << ", translation [" << flags.units << "] "
         << robot_noise.noise.robot_translation_sigma / metres << "\n"
         << std::setprecision(4) << "certificate: max ray error in [" << c.lower << ", " << c.upper
         << "] rad" << (c.certified ? " (certified)" : " (gap not closed)") << ", " << c.cubes
         << " cubes, " << c.lps << " LPs, " << c.seconds << " s\n"
         << "matches: " << global::PairCount(rechecked.inliers) << " inliers, "
         << rechecked.removed.size() << " removed (L∞ threshold " << robust.threshold
         << " rad, then the re-check at the polished X)\n";

  if (flags.output.empty()) return;
  nlohmann::json doc;
  doc["method"] = "global";
  doc["setup"] = std::string(handeye::SetupName(*setup));
  nlohmann::json x;
  x["frame"] = std::string(handeye::XFrameName(*setup));
  x["rotation"] = report::JsonRows(X.linear());
  x["translation_m"] = report::JsonVector(X.translation());
  doc["X"] = x;
  doc["certificate"] = {{"lower", c.lower},
                        {"upper", c.upper},
                        {"cubes", c.cubes},
                        {"lps", c.lps},
                        {"seconds", c.seconds},
                        {"certified", c.certified},
                        {"epsilon", flags.epsilon},
                        {"relative_gap", flags.relative_gap},
                        {"error", "max cheiral ray error, radians"},
                        {"reach_m", flags.reach}};
  doc["l_infinity_X"] = {{"rotation", report::JsonRows(robust.solution.X.linear())},
                         {"translation_m", report::JsonVector(robust.solution.X.translation())}};
  doc["covariance"] = {{"method", "linear, robot pose error marginalised"},
                       {"X", report::JsonRows(polish.covariance)},
                       {"convention", "right perturbation (rx, ry, rz, tx, ty, tz), rad and m"},
                       {"ray_sigma_rad", robot_noise.noise.ray_sigma},
                       {"robot_rotation_sigma_rad", robot_noise.noise.robot_rotation_sigma},
                       {"robot_translation_sigma_m", robot_noise.noise.robot_translation_sigma},
                       {"independent_pairs_X", report::JsonRows(rechecked.polish.covariance)}};
  doc["polish"] = {{"rms_rad", polish.rms}, {"pairs", polish.pairs}};
  doc["matches"] = {{"inliers", global::PairCount(rechecked.inliers)},
                    {"threshold_rad", robust.threshold},
                    {"pixel_threshold_rad", outliers.threshold},
                    {"error_scale_rad", robust.error_scale},
                    {"pixel_sigma", pixel_sigma}};
  nlohmann::json removed = nlohmann::json::array();
  for (const auto& [motion, id] : rechecked.removed) {
    const auto by = stage.find({motion, id});
    removed.push_back({{"first", input.motion_names[motion].first},
                       {"second", input.motion_names[motion].second},
                       {"id", id},
                       {"by", by != stage.end() ? by->second : "re-check at the polished X"}});
  }
  doc["matches"]["removed"] = removed;
  io::WriteFileAtomically(flags.output, doc.dump(2) + "\n");
  io.out << "wrote " << flags.output << "\n";
}

}  // namespace hecal::cli
