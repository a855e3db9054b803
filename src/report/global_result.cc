// The result of the target-free calibration and its file: see global_result.h.
#include "hecal/report/global_result.h"

#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

#include "hecal/core/options_check.h"
#include "hecal/estimation/reprojection_refinement.h"
#include "hecal/io/atomic_file.h"
#include "hecal/report/json_matrix.h"
#include "hecal/report/translation_sigma.h"

namespace hecal::report {
namespace {

constexpr const char* kOptions = "GlobalCalibrationOptions.";

std::string Field(const char* name) {
  return std::string(kOptions) + name;
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
  nlohmann::json motions = nlohmann::json::array();
  for (const MotionResidual& m : result.motions) {
    motions.push_back({{"first", m.first},
                       {"second", m.second},
                       {"pairs", m.pairs},
                       {"removed", m.removed},
                       {"rms_rad", m.rms},
                       {"max_rad", m.max}});
  }
  doc["motions"] = motions;
  doc["warnings"] = result.warnings;
  return doc.dump(2) + "\n";
}

void WriteGlobalResult(const std::string& path, const GlobalCalibrationResult& result) {
  io::WriteFileAtomically(path, GlobalResultJson(result));
}

}  // namespace hecal::report
