// The study tables as text: see study_text.h.
#include "hecal/report/study_text.h"

#include <optional>
#include <string>
#include <vector>

#include "hecal/estimation/methods.h"
#include "hecal/geometry/angle_units.h"
#include "hecal/report/text_table.h"
#include "hecal/study/study_csv.h"

namespace hecal::report {
namespace {

// Consistency of the predicted covariances of X (study.h), one line per method.
void PrintConsistency(const study::StudyResult& result, size_t setting, std::ostream& out) {
  bool header = false;
  for (const study::MethodSummary& m : result.summaries) {
    if (m.setting != static_cast<int>(setting) || !m.consistency) continue;
    const uncertainty::Consistency& c = *m.consistency;
    if (!header) {
      out << "  consistency of the predicted covariance of X (NEES: 6 dof; coverage: 68.3% / "
             "95.4% if consistent; sd: predicted/empirical)\n  "
          << Pad("method", 18, true) << Pad("NEES", 8) << Pad("95% band", 16) << Pad("", 4)
          << Pad("1σ cov", 9) << Pad("2σ cov", 9) << "  sd rx    ry    rz    tx    ty    tz\n";
      header = true;
    }
    const bool in_band = c.band.Contains(c.mean_nees);
    out << "  " << Pad(std::string(estimation::Info(m.method).name), 18, true)
        << Pad(Fixed(c.mean_nees, 2), 8)
        << Pad(std::string("[") + Fixed(c.band.low, 2) + ", " + Fixed(c.band.high, 2) + "]", 16)
        << Pad(in_band ? "ok" : "out", 4) << Pad(Fixed(100.0 * c.coverage_1sigma, 1) + "%", 9)
        << Pad(Fixed(100.0 * c.coverage_2sigma, 1) + "%", 9) << " ";
    for (Eigen::Index j = 0; j < c.sd_ratio.size(); ++j) out << Pad(Fixed(c.sd_ratio(j), 2), 6);
    out << "\n";
    if (m.consistency_model) {
      const uncertainty::Consistency& o = *m.consistency_model;
      out << "  " << Pad("  model only", 18, true) << Pad(Fixed(o.mean_nees, 2), 8) << Pad("", 16)
          << Pad(o.band.Contains(o.mean_nees) ? "ok" : "out", 4)
          << Pad(Fixed(100.0 * o.coverage_1sigma, 1) + "%", 9)
          << Pad(Fixed(100.0 * o.coverage_2sigma, 1) + "%", 9) << " ";
      for (Eigen::Index j = 0; j < o.sd_ratio.size(); ++j) out << Pad(Fixed(o.sd_ratio(j), 2), 6);
      out << " (check inflated " << m.check_used << " of " << (m.trials - m.failures) << ")\n";
    }
  }
}

// Outlier rejection per method (with --reject-outliers or --outliers), one line per method.
void PrintRejection(const study::StudyResult& result, size_t setting, std::ostream& out) {
  const study::Setting& s = result.options.settings[setting];
  if (!result.options.reject_outliers && s.gross_outliers == 0) return;
  out << "  " << Pad("method", 18, true) << Pad("found", 9) << Pad("all found", 11)
      << Pad("good rej", 10) << Pad("rmse clean", 12) << Pad("ratio", 7)
      << Pad("rmse clean [mm]", 17) << Pad("ratio", 7) << "\n";
  for (const study::MethodSummary& m : result.summaries) {
    if (m.setting != static_cast<int>(setting)) continue;
    const auto percent = [](int part, int whole) {
      return whole > 0 ? Fixed(100.0 * part / whole, 1) + "%" : std::string("-");
    };
    out << "  " << Pad(std::string(estimation::Info(m.method).name), 18, true)
        << Pad(percent(m.outliers_rejected, m.outliers_injected), 9)
        << Pad(percent(m.trials_all_found, m.trials - m.failures), 11)
        << Pad(percent(m.good_rejected, m.good_stations), 10)
        << Pad(Readable(m.rotation_rmse_clean * kDegreesPerRadian), 12)
        << Pad(Fixed(m.rotation.rmse / m.rotation_rmse_clean, 3), 7)
        << Pad(Readable(m.translation_rmse_clean * 1000.0), 17)
        << Pad(Fixed(m.translation.rmse / m.translation_rmse_clean, 3), 7) << "\n";
  }
}

std::string ErrorText(const std::optional<double>& value, double scale) {
  if (!value) return "-";
  const double v = *value * scale;
  return v != 0.0 && v < 1e-3 ? Printf("%.1e", v) : Printf("%.4f", v);
}

// The noise level as typed: "n" when millimetres and degrees agree, else "MM/DEG".
std::string LevelText(const study::NoiseLevel& sigma) {
  return sigma.mm == sigma.deg
             ? study::FormatNumber(sigma.mm)
             : study::FormatNumber(sigma.mm) + "/" + study::FormatNumber(sigma.deg);
}

}  // namespace

void PrintStudyTable(std::ostream& out, const study::StudyResult& result) {
  const auto& settings = result.options.settings;
  size_t row = 0;
  for (size_t s = 0; s < settings.size(); ++s) {
    const study::Setting& setting = settings[s];
    out << handeye::SetupName(setting.setup) << ", " << setting.stations << " stations, "
        << sim::NoiseKindName(setting.noise_kind) << " noise on "
        << study::NoiseOnName(setting.noise_on) << ", sigma "
        << study::FormatNumber(setting.translation_sigma * 1000.0) << " mm / "
        << study::FormatNumber(setting.rotation_sigma * kDegreesPerRadian) << " deg, "
        << result.options.trials << " trials";
    if (setting.robot_scale != 1.0)
      out << ", robot noise " << study::FormatNumber(setting.robot_scale) << "x";
    if (setting.gross_outliers > 0) {
      out << ", " << setting.gross_outliers << " gross outlier(s) per data set";
    }
    out << "\n";
    const study::Bound& bound = result.setting_bounds[s];
    out << "  first-order bound (ml at the truth): rotation RMSE "
        << Readable(bound.rotation * kDegreesPerRadian) << " deg, translation RMSE "
        << Readable(bound.translation * 1000.0) << " mm\n";
    out << "  " << Pad("method", 18, true) << Pad("fail", 5) << Pad("outl", 5)
        << Pad("rot median", 12) << Pad("rmse", 10) << Pad("p10", 10) << Pad("p90", 10)
        << Pad("max [deg]", 11) << Pad("tra median", 12) << Pad("rmse", 10) << Pad("p10", 10)
        << Pad("p90", 10) << Pad("max [mm]", 11) << "\n";
    for (; row < result.summaries.size() && result.summaries[row].setting == static_cast<int>(s);
         ++row) {
      const study::MethodSummary& m = result.summaries[row];
      out << "  " << Pad(std::string(estimation::Info(m.method).name), 18, true)
          << Pad(std::to_string(m.failures), 5) << Pad(std::to_string(m.outliers), 5)
          << Pad(Readable(m.rotation.median * kDegreesPerRadian), 12)
          << Pad(Readable(m.rotation.rmse * kDegreesPerRadian), 10)
          << Pad(Readable(m.rotation.p10 * kDegreesPerRadian), 10)
          << Pad(Readable(m.rotation.p90 * kDegreesPerRadian), 10)
          << Pad(Readable(m.rotation.max * kDegreesPerRadian), 11)
          << Pad(Readable(m.translation.median * 1000.0), 12)
          << Pad(Readable(m.translation.rmse * 1000.0), 10)
          << Pad(Readable(m.translation.p10 * 1000.0), 10)
          << Pad(Readable(m.translation.p90 * 1000.0), 10)
          << Pad(Readable(m.translation.max * 1000.0), 11) << "\n";
    }
    PrintConsistency(result, s, out);
    PrintRejection(result, s, out);
    out << "\n";
  }
}

void PrintBenchTable(std::ostream& out, const study::BenchResult& result) {
  const study::BenchOptions& o = result.options;
  const std::vector<study::BenchRow>& rows = result.rows;
  out << "hecal bench: thesis protocol, " << handeye::SetupName(o.setup) << ", Gaussian noise "
      << LevelText(o.sigma) << " (mm/deg) on robot and camera, " << o.datasets
      << " data sets per station count, seed " << o.seed
      << "; errors of X are RMS over data sets; fail = threw, "
         "non-finite or > 10 deg\n";
  out << Pad("method", 18, true) << Pad("n", 4) << Pad("hecal us", 12) << Pad("opencv us", 12)
      << Pad("speed-up", 10) << Pad("hecal deg", 11) << Pad("hecal mm", 10) << Pad("fail", 5)
      << Pad("opencv deg", 12) << Pad("opencv mm", 11) << Pad("fail", 5) << "\n";
  for (const study::BenchRow& row : rows) {
    if (row.impl != "hecal" || row.start == study::BenchStart::kGood) continue;
    const study::BenchRow* peer = nullptr;
    for (const study::BenchRow& other : rows) {
      if (other.impl == "opencv" && other.method == row.method && other.stations == row.stations) {
        peer = &other;
      }
    }
    out << Pad(std::string(estimation::Info(row.method).name), 18, true)
        << Pad(std::to_string(row.stations), 4) << Pad(Printf("%.2f", row.us_per_solve), 12)
        << Pad(peer ? Printf("%.2f", peer->us_per_solve) : "-", 12)
        << Pad(peer ? Printf("%.1fx", peer->us_per_solve / row.us_per_solve) : "-", 10)
        << Pad(ErrorText(row.accuracy.rotation_error, kDegreesPerRadian), 11)
        << Pad(ErrorText(row.accuracy.translation_error, 1000.0), 10)
        << Pad(std::to_string(row.accuracy.failures), 5)
        << Pad(peer ? ErrorText(peer->accuracy.rotation_error, kDegreesPerRadian) : "-", 12)
        << Pad(peer ? ErrorText(peer->accuracy.translation_error, 1000.0) : "-", 11)
        << Pad(peer ? std::to_string(peer->accuracy.failures) : "-", 5) << "\n";
  }
  out << "speed-up = OpenCV time / hecal time (> 1: hecal is faster)\n";
  for (const study::BenchRow& row : rows) {
    if (row.start != study::BenchStart::kGood) continue;
    const study::BenchRow* multi = nullptr;
    for (const study::BenchRow& other : rows) {
      if (other.start == study::BenchStart::kClosedForm && other.method == row.method &&
          other.stations == row.stations) {
        multi = &other;
      }
    }
    out << estimation::Info(row.method).name << " from a good start, n = " << row.stations << ": "
        << Printf("%.2f", row.us_per_solve) << " us per solve"
        << (multi ? Printf(", %.1fx faster than from the closed-form starts",
                           multi->us_per_solve / row.us_per_solve)
                  : std::string())
        << " (X " << ErrorText(row.accuracy.rotation_error, kDegreesPerRadian) << " deg / "
        << ErrorText(row.accuracy.translation_error, 1000.0) << " mm, " << row.accuracy.failures
        << " fail)\n";
  }
}

}  // namespace hecal::report
