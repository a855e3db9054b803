// The page data of `hecal simulate --report`: see simulate_page.h.
#include "hecal/report/simulate_page.h"

#include <cmath>
#include <string>
#include <vector>

#include "hecal/estimation/methods.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/study/study_csv.h"

namespace hecal::report {
namespace {

using nlohmann::json;

// NaN and ±inf as null (JSON has no such numbers; the page draws a gap).
json Number(double value) {
  return std::isfinite(value) ? json(value) : json(nullptr);
}

json Statistics(const sim::SummaryStatistics& s, double scale) {
  return {{"median", Number(s.median * scale)},
          {"rmse", Number(s.rmse * scale)},
          {"p10", Number(s.p10 * scale)},
          {"p90", Number(s.p90 * scale)},
          {"max", Number(s.max * scale)}};
}

json ConsistencyJson(const uncertainty::Consistency& c) {
  json sd = json::array();
  for (Eigen::Index j = 0; j < c.sd_ratio.size(); ++j) sd.push_back(Number(c.sd_ratio(j)));
  return {{"trials", c.trials},
          {"mean_nees", Number(c.mean_nees)},
          {"band", {Number(c.band.low), Number(c.band.high)}},
          {"coverage_1sigma", Number(c.coverage_1sigma)},
          {"coverage_2sigma", Number(c.coverage_2sigma)},
          {"sd_ratio", sd}};
}

json MethodJson(const study::MethodSummary& m) {
  json out = {{"method", std::string(estimation::Info(m.method).name)},
              {"trials", m.trials},
              {"failures", m.failures},
              {"outliers", m.outliers},
              {"rotation_deg", Statistics(m.rotation, kDegreesPerRadian)},
              {"translation_mm", Statistics(m.translation, 1000.0)},
              {"rotation_rmse_inliers_deg", Number(m.rotation_rmse_inliers * kDegreesPerRadian)},
              {"translation_rmse_inliers_mm", Number(m.translation_rmse_inliers * 1000.0)},
              {"worst_rotation_over_bound", Number(m.worst_rotation_over_bound)},
              {"worst_translation_over_bound", Number(m.worst_translation_over_bound)}};
  if (m.consistency) out["consistency"] = ConsistencyJson(*m.consistency);
  if (m.consistency_model) {
    out["consistency_model"] = ConsistencyJson(*m.consistency_model);
    out["check_used"] = m.check_used;
  }
  out["rejection"] = {
      {"outliers_injected", m.outliers_injected},
      {"outliers_rejected", m.outliers_rejected},
      {"good_stations", m.good_stations},
      {"good_rejected", m.good_rejected},
      {"trials_all_found", m.trials_all_found},
      {"rotation_rmse_clean_deg", Number(m.rotation_rmse_clean * kDegreesPerRadian)},
      {"translation_rmse_clean_mm", Number(m.translation_rmse_clean * 1000.0)}};
  return out;
}

// "eye-in-hand, 10 stations, gaussian on both, 0.3 mm / 0.3°" and the sweep's other fields.
std::string Label(const study::Setting& s) {
  std::string label = std::string(handeye::SetupName(s.setup)) + ", " + std::to_string(s.stations) +
                      " stations, " + std::string(sim::NoiseKindName(s.noise_kind)) + " on " +
                      std::string(study::NoiseOnName(s.noise_on)) + ", " +
                      study::FormatNumber(s.translation_sigma * 1000.0) + " mm / " +
                      study::FormatNumber(s.rotation_sigma * kDegreesPerRadian) + "°";
  if (s.robot_scale != 1.0) label += ", robot ×" + study::FormatNumber(s.robot_scale);
  if (s.gross_outliers > 0) label += ", " + std::to_string(s.gross_outliers) + " gross outliers";
  return label;
}

json SettingJson(const study::Setting& s, const study::Bound& bound) {
  return {{"label", Label(s)},
          {"setup", std::string(handeye::SetupName(s.setup))},
          {"stations", s.stations},
          {"noise_on", std::string(study::NoiseOnName(s.noise_on))},
          {"noise", std::string(sim::NoiseKindName(s.noise_kind))},
          {"sigma_mm", s.translation_sigma * 1000.0},
          {"sigma_deg", s.rotation_sigma * kDegreesPerRadian},
          {"robot_scale", s.robot_scale},
          {"gross_outliers", s.gross_outliers},
          {"bound",
           {{"rotation_deg", Number(bound.rotation * kDegreesPerRadian)},
            {"translation_mm", Number(bound.translation * 1000.0)}}},
          {"methods", json::array()}};
}

}  // namespace

json SimulatePageData(const study::StudyResult& result, const std::string& title) {
  const study::StudyOptions& o = result.options;
  json methods = json::array();
  for (const estimation::Method m : o.methods) {
    methods.push_back(std::string(estimation::Info(m).name));
  }
  json settings = json::array();
  for (size_t s = 0; s < o.settings.size(); ++s) {
    settings.push_back(SettingJson(o.settings[s], result.setting_bounds[s]));
  }
  for (const study::MethodSummary& m : result.summaries) {
    settings[static_cast<size_t>(m.setting)]["methods"].push_back(MethodJson(m));
  }
  // Trials are setting-major, then trial, then method (study.h): an even sample of the trial
  // indices, the same for every setting and method.
  const size_t n = static_cast<size_t>(o.trials);
  const size_t stride =
      n <= kMaxPlottedTrials ? 1 : (n + kMaxPlottedTrials - 1) / kMaxPlottedTrials;
  json trials = json::array();
  for (size_t s = 0; s < o.settings.size(); ++s) {
    json per_method = json::array();
    for (size_t k = 0; k < o.methods.size(); ++k) {
      per_method.push_back({{"rotation_deg", json::array()}, {"translation_mm", json::array()}});
    }
    trials.push_back(std::move(per_method));
  }
  for (const study::TrialResult& t : result.trials) {
    if (static_cast<size_t>(t.trial) % stride != 0 || t.status != study::TrialStatus::kOk) continue;
    size_t k = 0;
    while (k < o.methods.size() && o.methods[k] != t.method) ++k;
    json& cell = trials[static_cast<size_t>(t.setting)][k];
    cell["rotation_deg"].push_back(Number(t.rotation_error * kDegreesPerRadian));
    cell["translation_mm"].push_back(Number(t.translation_error * 1000.0));
  }
  const std::string covariance =
      o.covariance.method ? std::string(estimation::CovarianceMethodName(*o.covariance.method))
                          : std::string("default");
  return {{"kind", "simulate"},
          {"title", title},
          {"seed", o.seed},
          {"trials_per_setting", o.trials},
          {"covariance", covariance},
          {"reject_outliers", o.reject_outliers},
          {"estimate_noise", o.estimate_noise},
          {"methods", methods},
          {"settings", settings},
          {"trials", trials},
          {"trials_total", n},
          {"trials_sampled", stride > 1}};
}

}  // namespace hecal::report
