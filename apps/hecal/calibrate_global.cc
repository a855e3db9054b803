// `hecal calibrate --method global` (calibrate.h: RunCalibrateGlobal).
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
#include "hecal/geometry/so3.h"
#include "hecal/global/outlier_removal.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/camera_file.h"
#include "hecal/io/correspondence_file.h"
#include "hecal/io/units.h"
#include "json_matrix.h"

namespace hecal::cli {
namespace {

struct GlobalInput {
  global::EpipolarProblem problem;
  std::vector<std::pair<std::string, std::string>> motion_names;
  double focal = 1.0;  // pixels (1 for bearings)
};

GlobalInput ReadGlobalInput(const CalibrateFlags& flags, handeye::Setup setup) {
  if (!flags.camera.empty() || !flags.images.empty()) {
    throw InputError(flags.camera.empty() ? "--images" : "--camera", 0,
                     "--method global reads point matches, not camera poses or images",
                     "give the matches with --correspondences FILE (docs/global.md)");
  }
  if (flags.correspondences.empty()) {
    throw InputError("--correspondences", 0, "--method global needs point matches",
                     "give --correspondences FILE (CSV: first,second,u1,v1,u2,v2; "
                     "docs/global.md)");
  }
  const auto units = io::ParseLengthUnit(flags.units);
  if (!units) throw InputError("--units", 0, "unknown unit '" + flags.units + "'", "use m or mm");
  io::PoseReadOptions read;
  read.units = *units;
  read.degrees = flags.degrees;
  read.invert = flags.robot_inverse;
  const io::PoseTable robot = io::ReadPoseTable(flags.robot, read);
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
          const auto normalised = pose::Undistort(*camera, ray.head<2>());
          if (!normalised) {
            throw InputError(flags.correspondences, motion.lines[k],
                             "pixel (" + std::to_string(ray.x()) + ", " + std::to_string(ray.y()) +
                                 ") cannot be undistorted",
                             "check the pixel against the image size and the intrinsics");
          }
          ray = Eigen::Vector3d(normalised->x(), normalised->y(), 1.0).normalized();
        }
      }
      out.pairs.push_back({rays[0], rays[1], motion.ids[k]});
    }
    input.problem.motions.push_back(std::move(out));
    input.motion_names.emplace_back(motion.first, motion.second);
  }
  return input;
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
  if (!(flags.reach > 0.0 && flags.reach <= 1000.0)) {
    throw InputError("--reach", 0, "must be above 0 and at most 1000 m",
                     "give the largest camera offset from the hand in metres, e.g. 2");
  }
  const int threads = ParseThreads("--threads", flags.threads);
  const std::uint64_t seed = ParseSeed("--seed", flags.seed);
  double pixel_sigma = 0.5;
  if (!flags.pixel_sigma.empty()) {
    std::istringstream in(flags.pixel_sigma);
    if (!(in >> pixel_sigma) || !std::isfinite(pixel_sigma)) {
      throw InputError("--pixel-sigma", 0, "'" + flags.pixel_sigma + "' is not a number",
                       "give the pixel noise per axis in pixels, e.g. 0.5");
    }
    CheckPixelSigma("--pixel-sigma", pixel_sigma);
  }
  const GlobalInput input = ReadGlobalInput(flags, *setup);
  global::SearchOptions search;
  search.epsilon = flags.epsilon;
  search.translation_bound = flags.reach;
  search.threads = threads;
  global::OutlierOptions outliers;
  outliers.threshold = 4.0 * std::sqrt(2.0) * pixel_sigma / input.focal;
  outliers.seed = seed;
  const global::RobustGlobalSolution robust =
      global::SolveGlobalRobust(input.problem, search, outliers);
  const estimation::EpipolarPolish polish =
      estimation::PolishEpipolar(robust.inliers, robust.solution.X);
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
         << std::setprecision(4) << "certificate: max ray error in [" << c.lower << ", " << c.upper
         << "] rad" << (c.certified ? " (certified)" : " (gap not closed)") << ", " << c.cubes
         << " cubes, " << c.lps << " LPs, " << c.seconds << " s\n"
         << "matches: " << global::PairCount(robust.inliers) << " inliers, "
         << robust.removed.size() << " removed\n";

  if (flags.output.empty()) return;
  nlohmann::json doc;
  doc["method"] = "global";
  doc["setup"] = std::string(handeye::SetupName(*setup));
  nlohmann::json x;
  x["frame"] = std::string(handeye::XFrameName(*setup));
  x["rotation"] = JsonRows(X.linear());
  x["translation_m"] = JsonVector(X.translation());
  doc["X"] = x;
  doc["certificate"] = {{"lower", c.lower},         {"upper", c.upper},
                        {"cubes", c.cubes},         {"lps", c.lps},
                        {"seconds", c.seconds},     {"certified", c.certified},
                        {"epsilon", flags.epsilon}, {"error", "max cheiral ray error, radians"},
                        {"reach_m", flags.reach}};
  doc["l_infinity_X"] = {{"rotation", JsonRows(robust.solution.X.linear())},
                         {"translation_m", JsonVector(robust.solution.X.translation())}};
  doc["covariance"] = {{"method", "linear"},
                       {"X", JsonRows(polish.covariance)},
                       {"convention", "right perturbation (rx, ry, rz, tx, ty, tz), rad and m"},
                       {"ray_sigma_rad", polish.ray_sigma}};
  doc["polish"] = {{"rms_rad", polish.rms}, {"pairs", polish.pairs}};
  doc["matches"] = {{"inliers", global::PairCount(robust.inliers)},
                    {"threshold_rad", outliers.threshold},
                    {"pixel_sigma", pixel_sigma}};
  nlohmann::json removed = nlohmann::json::array();
  for (const global::RemovedPair& r : robust.removed) {
    removed.push_back({{"first", input.motion_names[r.motion].first},
                       {"second", input.motion_names[r.motion].second},
                       {"id", r.id},
                       {"by", r.by_prefilter ? "epipolar ransac" : "l-infinity support set"}});
  }
  doc["matches"]["removed"] = removed;
  io::WriteFileAtomically(flags.output, doc.dump(2) + "\n");
  io.out << "wrote " << flags.output << "\n";
}

}  // namespace hecal::cli
