#include "hecal/study/study_csv.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "hecal/geometry/angle_units.h"

namespace hecal::study {
namespace {
constexpr double kMm = 1000.0;

std::string Quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out + "\"";
}

// The setting's leading columns: setup,stations,noise_on,noise,sigma_mm,sigma_deg
std::string SettingColumns(const Setting& s) {
  return std::string(handeye::SetupName(s.setup)) + "," + std::to_string(s.stations) + "," +
         std::string(NoiseOnName(s.noise_on)) + "," +
         std::string(sim::NoiseKindName(s.noise_kind)) + "," +
         FormatNumber(s.translation_sigma * kMm) + "," +
         FormatNumber(s.rotation_sigma * kDegreesPerRadian);
}

void AppendStatistics(std::ostringstream& out, const sim::SummaryStatistics& s, double rmse_inliers,
                      double scale) {
  out << FormatNumber(s.median * scale) << ',' << FormatNumber(s.rmse * scale) << ','
      << FormatNumber(s.p10 * scale) << ',' << FormatNumber(s.p90 * scale) << ','
      << FormatNumber(s.max * scale) << ',' << FormatNumber(rmse_inliers * scale);
}

}  // namespace

std::string FormatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.9g", value);
  return buffer;
}

std::string TrialsCsv(const StudyResult& result) {
  std::ostringstream out;
  out << "setup,stations,noise_on,noise,sigma_mm,sigma_deg,trial,method,status,"
         "rotation_error_deg,translation_error_mm,outlier,bound_rotation_deg,"
         "bound_translation_mm,nees,message,gross_outliers,rejected_outliers,rejected_good,"
         "rotation_error_clean_deg,translation_error_clean_mm,robot_scale,nees_model,check_used,"
         "robot_sigma_deg,robot_sigma_mm\n";
  for (const TrialResult& trial : result.trials) {
    const Setting& setting = result.options.settings[trial.setting];
    const Bound& bound = result.bounds[trial.setting][trial.trial];
    out << SettingColumns(setting) << ',' << trial.trial << ','
        << estimation::Info(trial.method).name << ',' << TrialStatusName(trial.status) << ','
        << FormatNumber(trial.rotation_error * kDegreesPerRadian) << ','
        << FormatNumber(trial.translation_error * kMm) << ',' << (trial.outlier ? 1 : 0) << ','
        << FormatNumber(bound.rotation * kDegreesPerRadian) << ','
        << FormatNumber(bound.translation * kMm) << ',' << FormatNumber(trial.nees) << ','
        << (trial.message.empty() ? std::string() : Quoted(trial.message)) << ','
        << setting.gross_outliers << ',' << trial.rejected_outliers << ',' << trial.rejected_good
        << ',' << FormatNumber(trial.rotation_error_clean * kDegreesPerRadian) << ','
        << FormatNumber(trial.translation_error_clean * kMm) << ','
        << FormatNumber(setting.robot_scale) << ',' << FormatNumber(trial.nees_model) << ','
        << (trial.check_used ? 1 : 0) << ','
        << FormatNumber(trial.robot_sigma.rotation * kDegreesPerRadian) << ','
        << FormatNumber(trial.robot_sigma.translation * kMm) << '\n';
  }
  return out.str();
}

std::string SummaryCsv(const StudyResult& result) {
  std::ostringstream out;
  out << "setup,stations,noise_on,noise,sigma_mm,sigma_deg,method,trials,failures,outliers,"
         "rotation_median_deg,rotation_rmse_deg,rotation_p10_deg,rotation_p90_deg,"
         "rotation_max_deg,rotation_rmse_inliers_deg,translation_median_mm,translation_rmse_mm,"
         "translation_p10_mm,translation_p90_mm,translation_max_mm,translation_rmse_inliers_mm,"
         "bound_rotation_rmse_deg,bound_translation_rmse_mm,worst_rotation_over_bound,"
         "worst_translation_over_bound,mean_nees,nees_band_low,nees_band_high,coverage_1sigma,"
         "coverage_2sigma,sd_ratio_rx,sd_ratio_ry,sd_ratio_rz,sd_ratio_tx,sd_ratio_ty,"
         "sd_ratio_tz,gross_outliers,outliers_found,good_rejected,trials_all_found,"
         "rotation_rmse_clean_deg,translation_rmse_clean_mm,robot_scale,mean_nees_model,"
         "coverage_1sigma_model,coverage_2sigma_model,sd_ratio_model_rx,sd_ratio_model_ry,"
         "sd_ratio_model_rz,sd_ratio_model_tx,sd_ratio_model_ty,sd_ratio_model_tz,"
         "check_used\n";
  for (const MethodSummary& s : result.summaries) {
    const Bound& bound = result.setting_bounds[s.setting];
    out << SettingColumns(result.options.settings[s.setting]) << ','
        << estimation::Info(s.method).name << ',' << s.trials << ',' << s.failures << ','
        << s.outliers << ',';
    AppendStatistics(out, s.rotation, s.rotation_rmse_inliers, kDegreesPerRadian);
    out << ',';
    AppendStatistics(out, s.translation, s.translation_rmse_inliers, kMm);
    out << ',' << FormatNumber(bound.rotation * kDegreesPerRadian) << ','
        << FormatNumber(bound.translation * kMm) << ',' << FormatNumber(s.worst_rotation_over_bound)
        << ',' << FormatNumber(s.worst_translation_over_bound);
    if (s.consistency) {
      const uncertainty::Consistency& c = *s.consistency;
      out << ',' << FormatNumber(c.mean_nees) << ',' << FormatNumber(c.band.low) << ','
          << FormatNumber(c.band.high) << ',' << FormatNumber(c.coverage_1sigma) << ','
          << FormatNumber(c.coverage_2sigma);
      for (Eigen::Index j = 0; j < c.sd_ratio.size(); ++j)
        out << ',' << FormatNumber(c.sd_ratio(j));
    } else {
      out << ",nan,nan,nan,nan,nan,nan,nan,nan,nan,nan,nan";
    }
    const auto fraction = [](int part, int whole) {
      return whole > 0 ? static_cast<double>(part) / whole : std::nan("");
    };
    out << ',' << result.options.settings[s.setting].gross_outliers << ','
        << FormatNumber(fraction(s.outliers_rejected, s.outliers_injected)) << ','
        << FormatNumber(fraction(s.good_rejected, s.good_stations)) << ','
        << FormatNumber(fraction(s.trials_all_found, s.trials - s.failures)) << ','
        << FormatNumber(s.rotation_rmse_clean * kDegreesPerRadian) << ','
        << FormatNumber(s.translation_rmse_clean * kMm) << ','
        << FormatNumber(result.options.settings[s.setting].robot_scale);
    if (s.consistency_model) {
      const uncertainty::Consistency& c = *s.consistency_model;
      out << ',' << FormatNumber(c.mean_nees) << ',' << FormatNumber(c.coverage_1sigma) << ','
          << FormatNumber(c.coverage_2sigma);
      for (Eigen::Index j = 0; j < c.sd_ratio.size(); ++j)
        out << ',' << FormatNumber(c.sd_ratio(j));
      out << ',' << FormatNumber(fraction(s.check_used, s.trials - s.failures));
    } else {
      out << ",nan,nan,nan,nan,nan,nan,nan,nan,nan,nan";
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace hecal::study
