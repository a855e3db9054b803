// Target-free, globally optimal calibration as one job: see global_calibration.h.
#include "hecal/report/global_calibration.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <nlohmann/json.hpp>
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

namespace hecal::report {
namespace {

constexpr const char* kOptions = "GlobalCalibrationOptions.";

std::string Field(const char* name) {
  return std::string(kOptions) + name;
}

// A search that a budget stopped, in one sentence each (none when the gap closed).
std::vector<std::string> SearchWarnings(const global::Certificate& c,
                                        const GlobalCalibrationOptions& options) {
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

// covariance.model_check: the fields of the other methods' model check (result_file.cc) where
// they mean the same, for X only and in radians and metres, and the model's own covariance.
nlohmann::json ModelCheckJson(const GlobalCovarianceCheck& checked) {
  const estimation::ModelCheck& check = checked.check;
  if (!check.possible) {
    return {{"method", "jackknife"}, {"possible", false}, {"reason", check.reason}};
  }
  const auto per_axis = [](const Vector6d& v) {
    return nlohmann::json{{"rotation", {v(0), v(1), v(2)}}, {"translation", {v(3), v(4), v(5)}}};
  };
  const auto sigma = [](const Vector6d& v) {
    return nlohmann::json{{"rotation_rad", {v(0), v(1), v(2)}},
                          {"translation_m", {v(3), v(4), v(5)}}};
  };
  static const char* const kNames[6] = {"rx", "ry", "rz", "tx", "ty", "tz"};
  nlohmann::json flagged = nlohmann::json::array();
  for (int k = 0; k < 6; ++k) {
    if (check.flagged[std::size_t(k)]) flagged.push_back(std::string("X.") + kNames[k]);
  }
  return {{"method", "jackknife"},
          {"possible", true},
          {"groups", check.groups},
          {"sigma_model", {{"X", sigma(check.sigma_model.head<6>())}}},
          {"sigma_check", {{"X", sigma(check.sigma_check.head<6>())}}},
          {"ratio", {{"X", per_axis(check.Ratio().head<6>())}}},
          {"relative_error", {{"X", per_axis(check.relative_error.head<6>())}}},
          {"inflation", {{"X", per_axis(check.Inflation().head<6>())}}},
          {"flagged", flagged},
          {"used", check.used},
          {"model_X", JsonRows(Matrix6d(check.model_covariance.topLeftCorner<6, 6>()))}};
}

}  // namespace

bool GlobalCalibrationOptions::IsValid(std::string* why) const {
  if (!(epsilon > 0.0 && epsilon <= 1.0)) {
    return Invalid(why, Field("epsilon"), "must be above 0 and at most 1 rad",
                   "give the certificate's gap in radians, e.g. 2e-4");
  }
  if (!(matches_per_motion >= 8 && matches_per_motion <= 100000)) {
    return Invalid(why, Field("matches_per_motion"), "must be at least 8 and at most 100000",
                   "give how many matches per motion the search uses, e.g. 40");
  }
  if (!(relative_gap >= 0.0 && relative_gap < 1.0)) {
    return Invalid(why, Field("relative_gap"), "must be at least 0 and below 1",
                   "give the certificate's gap as a fraction of the optimum, e.g. 0.1 (0: only "
                   "the absolute gap epsilon)");
  }
  if (!(reach > 0.0 && reach <= 1000.0)) {
    return Invalid(why, Field("reach"), "must be above 0 and at most 1000 m",
                   "give the largest camera offset from the hand in metres, e.g. 2");
  }
  if (!(max_cubes >= 1)) {
    return Invalid(why, Field("max_cubes"), "must be at least 1",
                   "give the search's budget of cube tests, e.g. 1000000");
  }
  if (!(time_budget > 0.0 && time_budget <= 1e7)) {
    return Invalid(why, Field("time_budget"), "must be above 0 and at most 1e7 s",
                   "give the search's time in seconds, e.g. 120");
  }
  if (!ThreadCountValid(threads, Field("threads"), why)) return false;
  if (!estimation::PixelSigmaIsValid(pixel_sigma, Field("pixel_sigma"), why)) return false;
  return estimation::SigmaIsValid(robot_sigma, Field("robot_sigma"), why);
}

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

GlobalCalibrationResult CalibrateGlobal(
    const GlobalMatches& matches, const GlobalCalibrationOptions& options,
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

  GlobalCalibrationResult result;
  result.options = options;
  // The final X and covariance with the robot's pose error marginalised (the re-check above
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
  result.covariance_check = CheckGlobalCovariance(rechecked.inliers, result.robot_noise);
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
  return result;
}

std::string GlobalResultJson(const GlobalCalibrationResult& result) {
  const GlobalCalibrationOptions& options = result.options;
  const estimation::EpipolarPolish& polish = result.robot_noise.polish;
  const estimation::EpipolarNoise& noise = result.noise;
  const global::Certificate& c = result.certificate;
  const estimation::ModelCheck& check = result.covariance_check.check;
  nlohmann::json doc;
  doc["method"] = "global";
  doc["setup"] = std::string(handeye::SetupName(options.setup));
  nlohmann::json x;
  x["frame"] = std::string(handeye::XFrameName(options.setup));
  x["rotation"] = JsonRows(polish.X.linear());
  x["translation_m"] = JsonVector(polish.X.translation());
  doc["X"] = x;
  doc["certificate"] = {{"lower", c.lower},
                        {"upper", c.upper},
                        {"cubes", c.cubes},
                        {"lps", c.lps},
                        {"seconds", c.seconds},
                        {"certified", c.certified},
                        {"stopped_by", std::string(global::StopReasonName(c.stopped_by))},
                        {"time_budget_s", options.time_budget},
                        {"max_cubes", options.max_cubes},
                        {"search_seconds", result.search_seconds},
                        {"epsilon", options.epsilon},
                        {"relative_gap", options.relative_gap},
                        {"error", "max cheiral ray error, radians"},
                        {"reach_m", options.reach}};
  doc["l_infinity_X"] = {{"rotation", JsonRows(result.l_infinity_X.linear())},
                         {"translation_m", JsonVector(result.l_infinity_X.translation())}};
  doc["covariance"] = {
      {"method", check.used ? "linear, robot pose error marginalised, inflated by the model check"
                            : "linear, robot pose error marginalised"},
      {"X", JsonRows(polish.covariance)},
      {"convention", "right perturbation (rx, ry, rz, tx, ty, tz), rad and m"},
      {"ray_sigma_rad", noise.ray_sigma},
      {"robot_rotation_sigma_rad", noise.robot_rotation_sigma},
      {"robot_translation_sigma_m", noise.robot_translation_sigma},
      {"robot_sigma", result.robot_noise.robot_given ? "given" : "estimated"},
      {"independent_pairs_X", JsonRows(result.independent_covariance)},
      {"model_check", ModelCheckJson(result.covariance_check)},
      {"translation_in_parent", TranslationSigmaInParentJson(handeye::XFrameName(options.setup),
                                                             polish.X, polish.covariance, 1.0)}};
  doc["polish"] = {{"rms_rad", polish.rms}, {"pairs", polish.pairs}};
  doc["matches"] = {{"inliers", result.inliers},
                    {"threshold_rad", result.threshold},
                    {"pixel_threshold_rad", result.pixel_threshold},
                    {"error_scale_rad", result.error_scale},
                    {"pixel_sigma", options.pixel_sigma}};
  nlohmann::json removed = nlohmann::json::array();
  for (const RemovedMatch& r : result.removed) {
    removed.push_back({{"first", r.first}, {"second", r.second}, {"id", r.id}, {"by", r.by}});
  }
  doc["matches"]["removed"] = removed;
  doc["warnings"] = result.warnings;
  return doc.dump(2) + "\n";
}

void WriteGlobalResult(const std::string& path, const GlobalCalibrationResult& result) {
  io::WriteFileAtomically(path, GlobalResultJson(result));
}

}  // namespace hecal::report
