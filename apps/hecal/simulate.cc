// `hecal simulate`: see simulate.h.
#include "simulate.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <optional>

#include "bounds.h"
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/io/atomic_file.h"
#include "hecal/study/simulate.h"
#include "hecal/study/study_csv.h"
#include "list_flags.h"

namespace hecal::cli {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

constexpr const char* kFooter =
    R"(The thesis study (docs/thesis-study.md): thesis-protocol data sets (random hand-eye
transform, camera 1 m from the target, stations in a 1 m cube, +-45 deg tilt, free spin about
the optical axis), noise on the robot and/or camera poses, every method on the same data per
trial. Errors: angle of R_true^-1 R_est (deg) and translation distance (mm) of X.
List flags sweep: the study runs every combination (setup x noise-on x noise x sigma x stations).
--sigma levels: n = n mm and n deg per component (the thesis' "n mm / n deg"); MM/DEG for
  different values, e.g. --sigma 0,0.3,1,0.2/0.05. Uniform: half-width; systematic: offset.
--stations counts poses (k motions = k + 1 stations), at least 3.
Outliers: triangle threshold on a smoothed log-histogram of each setting's errors (per method).
Bound: first-order (Cramer-Rao-type) RMSE of the ml estimate at the truth, RMS over trials.
--covariance: every method is told the true noise model and predicts the covariance of X;
  NEES = e' C^-1 e of e = Log(X_est^-1 X_true), its mean should lie in the chi-square band,
  1-sigma / 2-sigma ellipsoid coverage should be 68.3% / 95.4%.
--outliers K: K stations per data set get a random robot pose; every method also solves the
  data set without them (the clean reference). --reject-outliers: every method runs through
  calibrate's outlier rejection; the table adds the fraction of gross outliers found, of good
  stations rejected, and the RMSE over the clean reference's RMSE.
Same --seed, same CSV files whatever --threads.)";

std::vector<study::NoiseLevel> ParseSigmaLevels(const std::string& text) {
  std::vector<study::NoiseLevel> levels;
  for (const std::string& item : SplitList("--sigma", text)) {
    levels.push_back(ParseNoiseLevel("--sigma", item, '/', /*single=*/true));
  }
  return levels;
}

std::string Fixed(double value, int precision) {
  if (!std::isfinite(value)) return study::FormatNumber(value);
  char buffer[48];
  std::snprintf(buffer, sizeof(buffer), "%.*f", precision, value);
  return buffer;
}

// Fixed-point for ordinary magnitudes, scientific for the tiny errors of noise-free data.
std::string Readable(double value) {
  if (std::isfinite(value) && value != 0.0 && std::abs(value) < 1e-3) {
    char buffer[48];
    std::snprintf(buffer, sizeof(buffer), "%.2e", value);
    return buffer;
  }
  return Fixed(value, 4);
}

std::string Pad(const std::string& text, size_t width, bool left_align = false) {
  if (text.size() >= width) return text;
  const std::string padding(width - text.size(), ' ');
  return left_align ? text + padding : padding + text;
}

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
    out << "  " << Pad(std::string(handeye::Info(m.method).name), 18, true)
        << Pad(Fixed(c.mean_nees, 2), 8)
        << Pad("[" + Fixed(c.band.low, 2) + ", " + Fixed(c.band.high, 2) + "]", 16)
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
    out << "  " << Pad(std::string(handeye::Info(m.method).name), 18, true)
        << Pad(percent(m.outliers_rejected, m.outliers_injected), 9)
        << Pad(percent(m.trials_all_found, m.trials - m.failures), 11)
        << Pad(percent(m.good_rejected, m.good_stations), 10)
        << Pad(Readable(m.rotation_rmse_clean * kDeg), 12)
        << Pad(Fixed(m.rotation.rmse / m.rotation_rmse_clean, 3), 7)
        << Pad(Readable(m.translation_rmse_clean * 1000.0), 17)
        << Pad(Fixed(m.translation.rmse / m.translation_rmse_clean, 3), 7) << "\n";
  }
}

void PrintTable(const study::StudyResult& result, std::ostream& out) {
  const auto& settings = result.options.settings;
  size_t row = 0;
  for (size_t s = 0; s < settings.size(); ++s) {
    const study::Setting& setting = settings[s];
    out << handeye::SetupName(setting.setup) << ", " << setting.stations << " stations, "
        << sim::NoiseKindName(setting.noise_kind) << " noise on "
        << study::NoiseOnName(setting.noise_on) << ", sigma "
        << study::FormatNumber(setting.translation_sigma * 1000.0) << " mm / "
        << study::FormatNumber(setting.rotation_sigma * kDeg) << " deg, " << result.options.trials
        << " trials";
    if (setting.robot_scale != 1.0)
      out << ", robot noise " << study::FormatNumber(setting.robot_scale) << "x";
    if (setting.gross_outliers > 0) {
      out << ", " << setting.gross_outliers << " gross outlier(s) per data set";
    }
    out << "\n";
    const study::Bound& bound = result.setting_bounds[s];
    out << "  first-order bound (ml at the truth): rotation RMSE "
        << Readable(bound.rotation * kDeg) << " deg, translation RMSE "
        << Readable(bound.translation * 1000.0) << " mm\n";
    out << "  " << Pad("method", 18, true) << Pad("fail", 5) << Pad("outl", 5)
        << Pad("rot median", 12) << Pad("rmse", 10) << Pad("p10", 10) << Pad("p90", 10)
        << Pad("max [deg]", 11) << Pad("tra median", 12) << Pad("rmse", 10) << Pad("p10", 10)
        << Pad("p90", 10) << Pad("max [mm]", 11) << "\n";
    for (; row < result.summaries.size() && result.summaries[row].setting == static_cast<int>(s);
         ++row) {
      const study::MethodSummary& m = result.summaries[row];
      out << "  " << Pad(std::string(handeye::Info(m.method).name), 18, true)
          << Pad(std::to_string(m.failures), 5) << Pad(std::to_string(m.outliers), 5)
          << Pad(Readable(m.rotation.median * kDeg), 12)
          << Pad(Readable(m.rotation.rmse * kDeg), 10) << Pad(Readable(m.rotation.p10 * kDeg), 10)
          << Pad(Readable(m.rotation.p90 * kDeg), 10) << Pad(Readable(m.rotation.max * kDeg), 11)
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

// One item of --setup, --noise-on, --noise: `parse` or an InputError listing `choices`.
template <typename T, typename Parse>
std::vector<T> ParseNames(const std::string& flag, const std::string& text, Parse parse,
                          const std::string& what, const std::string& choices) {
  std::vector<T> values;
  for (const std::string& item : SplitList(flag, text)) {
    const std::optional<T> value = parse(item);
    if (!value) throw InputError(flag, 0, "unknown " + what + " '" + item + "'", "use " + choices);
    values.push_back(*value);
  }
  return values;
}

std::vector<double> ParseNumbers(const std::string& flag, const std::string& text) {
  std::vector<double> values;
  for (const std::string& item : SplitList(flag, text)) {
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0') {
      throw InputError(flag, 0, "'" + item + "' is not a number", "e.g. " + flag + " 1,5");
    }
    values.push_back(value);
  }
  return values;
}

struct SimulateCommand {
  study::SimulateOptions options;
  std::string output;
  std::string summary;
};

void RunSimulate(const SimulateCommand& command, const Io& io) {
  std::string why;
  if (!command.options.IsValid(&why)) throw OptionsError(why);
  io::CheckOutputs({{"--output", command.output}, {"--summary", command.summary}}, {});
  const study::StudyResult result = study::Simulate(command.options);
  std::vector<io::OutputFile> outputs;
  if (!command.output.empty())
    outputs.push_back({"--output", command.output, study::TrialsCsv(result)});
  if (!command.summary.empty()) {
    outputs.push_back({"--summary", command.summary, study::SummaryCsv(result)});
  }
  io::WriteFilesAtomically(outputs);
  io.out << "hecal simulate: seed " << command.options.seed << "\n";
  PrintTable(result, io.out);
  if (!command.output.empty()) {
    io.out << "hecal: wrote per-trial errors to " << command.output << "\n";
  }
  if (!command.summary.empty()) {
    io.out << "hecal: wrote the summary to " << command.summary << "\n";
  }
}

}  // namespace

void RegisterSimulateCommand(CLI::App& app, const Io& io) {
  auto command = std::make_shared<SimulateCommand>();
  study::SimulateOptions& o = command->options;
  CLI::App* simulate = app.add_subcommand(
      "simulate", "The thesis study: every method on simulated data, errors and summaries");
  simulate
      ->add_option_function<std::string>(
          "--setup",
          [&o](const std::string& text) {
            o.setups = ParseNames<handeye::Setup>("--setup", text, handeye::ParseSetup, "setup",
                                                  "eye-in-hand or eye-to-hand (or both, comma "
                                                  "separated)");
          },
          "eye-in-hand | eye-to-hand (list sweeps)")
      ->default_str("eye-in-hand");
  AddWholeNumberList(*simulate, "--stations", o.stations,
                     "Stations per data set (list sweeps, 3 to 100000)")
      ->default_str("3,5,10,15,20");
  AddWholeNumber(*simulate, "--trials", o.trials, "Random data sets per setting (1 to 100000)")
      ->capture_default_str();
  simulate
      ->add_option_function<std::string>(
          "--noise-on",
          [&o](const std::string& text) {
            o.noise_on = ParseNames<study::NoiseOn>("--noise-on", text, study::ParseNoiseOn,
                                                    "value", "robot, camera or both");
          },
          "robot | camera | both (list sweeps)")
      ->default_str("both");
  simulate
      ->add_option_function<std::string>(
          "--noise",
          [&o](const std::string& text) {
            o.noise = ParseNames<sim::NoiseModel::Kind>(
                "--noise", text, sim::ParseNoiseKind, "noise kind",
                "gaussian, uniform, systematic, student-t3 or pnp");
          },
          "gaussian | uniform | systematic | student-t3 | pnp (camera) (list sweeps)")
      ->default_str("gaussian");
  simulate
      ->add_option_function<std::string>(
          "--sigma", [&o](const std::string& text) { o.sigmas = ParseSigmaLevels(text); },
          "Noise levels: n (= n mm and n deg per component) or MM/DEG (list sweeps)")
      ->default_str("0,0.3,1");
  simulate
      ->add_option_function<std::string>(
          "--method",
          [&o](const std::string& text) { o.methods = ParseMethodList("--method", text); },
          "Method name(s), comma separated, or all")
      ->default_str("all");
  AddWholeNumber(*simulate, "--seed", o.seed, "Random seed (0 to 2^64-1)")->capture_default_str();
  AddWholeNumber(*simulate, "--threads", o.threads, "Worker threads, 0 to 256 (0 = every core)")
      ->capture_default_str();
  simulate
      ->add_option_function<std::string>(
          "--covariance",
          [&o](const std::string& text) {
            if (text == "default") {
              o.covariance = std::nullopt;
              return;
            }
            o.covariance = estimation::ParseCovarianceMethod(text);
            if (!o.covariance) {
              throw InputError("--covariance", 0, "unknown covariance method '" + text + "'",
                               "use none, default, linear, unscented or montecarlo");
            }
          },
          "Predict X's covariance per trial and report its consistency: none | default "
          "(each method's own) | linear | unscented | montecarlo")
      ->default_str("none");
  AddWholeNumber(*simulate, "--covariance-samples", o.covariance_samples,
                 "Monte Carlo samples per trial with --covariance montecarlo (2 to 100000)")
      ->capture_default_str();
  AddWholeNumberList(
      *simulate, "--outliers", o.outliers,
      "Stations per data set given a random robot pose (gross outliers; list sweeps)")
      ->default_str("0");
  simulate->add_flag("--reject-outliers", o.reject_outliers,
                     "Every method through calibrate's outlier rejection (counts what it rejects)");
  simulate
      ->add_option_function<std::string>(
          "--robot-scale",
          [&o](const std::string& text) { o.robot_scales = ParseNumbers("--robot-scale", text); },
          "Robot noise = this times the level, camera noise = the level (list sweeps)")
      ->default_str("1");
  simulate->add_flag("--estimate-noise", o.estimate_noise,
                     "Tell no method the sigmas: estimated from the residuals (the default path)");
  simulate->add_option("--output", command->output, "Per-trial CSV (written atomically)");
  simulate->add_option("--summary", command->summary, "Summary CSV (written atomically)");
  simulate->footer(kFooter);
  simulate->callback([command, io] { RunSimulate(*command, io); });
}

}  // namespace hecal::cli
