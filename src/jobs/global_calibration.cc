// Target-free, globally optimal calibration as one job: see global_calibration.h.
#include "hecal/jobs/global_calibration.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/estimation/epipolar_polish.h"
#include "hecal/estimation/reprojection_refinement.h"
#include "hecal/global/outlier_removal.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/camera_file.h"
#include "hecal/io/correspondence_file.h"
#include "hecal/report/json_matrix.h"
#include "hecal/report/translation_sigma.h"

namespace hecal::jobs {
namespace {

// A search that a budget stopped, in one sentence each (none when the gap closed).
std::vector<std::string> SearchWarnings(const global::Certificate& c,
                                        const report::GlobalCalibrationOptions& options) {
  if (c.stopped_by != global::StopReason::kTimeBudget &&
      c.stopped_by != global::StopReason::kMaxCubes) {
    return {};
  }
  const bool time = c.stopped_by == global::StopReason::kTimeBudget;
  std::ostringstream text;
  text << std::setprecision(3) << "the global search stopped at its ";
  if (time) {
    text << "time budget (" << options.time_budget << " s)";
  } else {
    text << "cube budget (" << options.max_cubes << " cubes)";
  }
  text << " without closing the gap: max ray error in [" << c.lower << ", " << c.upper
       << "] rad, not certified; X is the polish from the best candidate found (give "
       << (time ? "--time-budget" : "--max-cubes") << " more to narrow the gap)";
  return {text.str()};
}

}  // namespace

GlobalMatches ReadGlobalMatches(const std::string& robot_file, const io::PoseReadOptions& read,
                                const std::string& correspondence_file,
                                const std::string& intrinsics_file) {
  const io::PoseTable robot = io::ReadPoseTable(robot_file, read);
  const io::CorrespondenceFile matches = io::ReadCorrespondenceFile(correspondence_file);
  std::optional<pose::CameraModel> camera;
  if (matches.pixels) {
    if (intrinsics_file.empty()) {
      throw InputError(correspondence_file, 0, "gives pixels, and no intrinsics file was given",
                       "give the camera's intrinsics file (camera.yaml), or write bearings "
                       "(x1,y1,z1,x2,y2,z2)");
    }
    camera = io::ReadCameraFile(intrinsics_file).camera;
  }
  // Stations: by id when every robot row has one, else by 1-based row number.
  const bool by_id = std::all_of(robot.rows.begin(), robot.rows.end(),
                                 [](const io::PoseRow& row) { return row.id.has_value(); });
  std::map<std::string, int> station;
  GlobalMatches out;
  for (std::size_t i = 0; i < robot.rows.size(); ++i) {
    station[by_id ? *robot.rows[i].id : std::to_string(i + 1)] = int(i);
    out.T_base_gripper.push_back(robot.rows[i].pose);
  }
  out.focal = camera ? 0.5 * (camera->fx + camera->fy) : 1.0;
  for (const io::CorrespondenceMotion& motion : matches.motions) {
    for (const std::string& name : {motion.first, motion.second}) {
      if (!station.count(name)) {
        throw InputError(correspondence_file, motion.line,
                         "station '" + name + "' is not in " + robot_file,
                         by_id ? "use the robot file's id column values"
                               : "number stations by the robot file's rows, from 1");
      }
    }
    GlobalMotion m;
    m.first = station[motion.first];
    m.second = station[motion.second];
    m.first_name = motion.first;
    m.second_name = motion.second;
    for (std::size_t k = 0; k < motion.ids.size(); ++k) {
      Eigen::Vector3d rays[2] = {motion.first_points[k], motion.second_points[k]};
      if (camera) {
        for (Eigen::Vector3d& ray : rays) {
          ray = pose::PixelRay(*camera, ray.head<2>(), correspondence_file, motion.lines[k]);
        }
      }
      m.pairs.push_back({rays[0], rays[1], motion.ids[k]});
    }
    out.motions.push_back(std::move(m));
  }
  return out;
}

report::GlobalCalibrationResult CalibrateGlobal(
    const GlobalMatches& matches, const report::GlobalCalibrationOptions& options,
    const std::function<void(const global::SearchProgress&)>& progress) {
  RequireValid(options);
  global::EpipolarProblem problem;
  problem.setup = options.setup;
  const int stations = int(matches.T_base_gripper.size());
  for (const GlobalMotion& motion : matches.motions) {
    for (const int index : {motion.first, motion.second}) {
      if (index < 0 || index >= stations) {
        throw InputError("GlobalMatches.motions", 0,
                         "motion " + motion.first_name + " → " + motion.second_name +
                             " names station " + std::to_string(index) + " of " +
                             std::to_string(stations),
                         "give station indices into T_base_gripper");
      }
    }
    global::EpipolarMotion m;
    m.first_station = motion.first;
    m.second_station = motion.second;
    m.hand = global::HandPose(options.setup, matches.T_base_gripper[std::size_t(motion.first)])
                 .inverse() *
             global::HandPose(options.setup, matches.T_base_gripper[std::size_t(motion.second)]);
    m.pairs = motion.pairs;
    problem.motions.push_back(std::move(m));
  }
  global::SearchOptions search;
  search.epsilon = options.epsilon;
  search.relative_gap = options.relative_gap;
  search.translation_bound = options.reach;
  search.max_cubes = options.max_cubes;
  search.time_budget = options.time_budget;
  search.progress = progress;
  search.threads = options.threads;
  global::OutlierOptions outliers;
  outliers.threshold = 4.0 * std::sqrt(2.0) * options.pixel_sigma / matches.focal;
  outliers.seed = options.seed;
  const global::RobustGlobalSolution robust = global::SolveGlobalRobust(problem, search, outliers);
  const estimation::RecheckedPolish rechecked =
      estimation::PolishAndRecheck(problem, robust.inliers, robust.solution.X);

  report::GlobalCalibrationResult result;
  result.options = options;
  // The final X and covariance with the robot's report::pose error marginalised (the re-check above
  // treats pairs as independent, which only decides which pairs to keep).
  std::optional<estimation::PoseSigma> hand_sigma;
  if (options.robot_sigma) {
    std::set<int> used;
    for (const GlobalMotion& motion : matches.motions) used.insert({motion.first, motion.second});
    double mean_squared_distance = 0.0;
    for (const int station : used) {
      mean_squared_distance +=
          matches.T_base_gripper[std::size_t(station)].translation().squaredNorm() /
          double(used.size());
    }
    hand_sigma =
        estimation::HandPoseSigma(options.setup, *options.robot_sigma, mean_squared_distance);
  }
  result.robot_noise = estimation::PolishWithEstimatedRobotNoise(
      rechecked.inliers, rechecked.polish.X, options.reach, hand_sigma);
  result.covariance_check = report::CheckGlobalCovariance(rechecked.inliers, result.robot_noise);
  result.robot_noise.polish.covariance = result.covariance_check.covariance;
  result.noise = result.robot_noise.noise;
  if (options.robot_sigma) {
    result.noise.robot_rotation_sigma = options.robot_sigma->rotation;
    result.noise.robot_translation_sigma = options.robot_sigma->translation;
  }
  result.independent_covariance = rechecked.polish.covariance;
  result.certificate = robust.solution.certificate;
  result.l_infinity_X = robust.solution.X;
  result.inliers = global::PairCount(rechecked.inliers);
  result.threshold = robust.threshold;
  result.pixel_threshold = outliers.threshold;
  result.error_scale = robust.error_scale;
  result.search_seconds = robust.seconds;
  result.warnings = SearchWarnings(result.certificate, options);
  if (!result.covariance_check.warning.empty()) {
    result.warnings.push_back(result.covariance_check.warning);
  }
  // The stage that removed each pair the re-check leaves out (pairs it re-admits are not listed).
  std::map<std::pair<int, int>, std::string> stage;
  for (const global::RemovedPair& r : robust.removed) {
    stage[{r.motion, r.id}] = r.by_prefilter ? "epipolar ransac" : "l-infinity support set";
  }
  for (const auto& [motion, id] : rechecked.removed) {
    const auto by = stage.find({motion, id});
    const GlobalMotion& m = matches.motions[std::size_t(motion)];
    result.removed.push_back({m.first_name, m.second_name, id,
                              by != stage.end() ? by->second : "re-check at the polished X"});
  }
  // Each motion's residuals at the final X (the re-check keeps the motions in order).
  for (std::size_t k = 0; k < matches.motions.size(); ++k) {
    report::MotionResidual residual{matches.motions[k].first_name, matches.motions[k].second_name};
    const global::EpipolarMotion& kept = rechecked.inliers.motions[k];
    double squares = 0.0;
    for (const global::BearingPair& pair : kept.pairs) {
      const double r =
          std::abs(estimation::SampsonAngle(result.robot_noise.polish.X, kept.hand, pair));
      squares += r * r;
      residual.max = std::max(residual.max, r);
    }
    residual.pairs = int(kept.pairs.size());
    residual.rms = kept.pairs.empty() ? 0.0 : std::sqrt(squares / double(kept.pairs.size()));
    for (const auto& [motion, id] : rechecked.removed) residual.removed += motion == int(k);
    result.motions.push_back(std::move(residual));
  }
  return result;
}
}  // namespace hecal::jobs
