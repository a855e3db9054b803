// `hecal simulate`: see simulate.h.
#include "simulate.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numbers>

#include "bounds.h"
#include "hecal/core/error.h"
#include "hecal/io/atomic_file.h"
#include "hecal/study/study.h"
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

std::vector<SigmaLevel> ParseSigmaLevels(const std::string& text) {
  std::vector<SigmaLevel> levels;
  for (const std::string& item : SplitList("--sigma", text)) {
    levels.push_back(ParseSigmaLevel("--sigma", item));
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

}  // namespace

void RunSimulate(const SimulateFlags& flags, const Io& io) {
  study::StudyOptions options;
  std::vector<handeye::Setup> setups;
  for (const std::string& item : SplitList("--setup", flags.setup)) {
    const std::optional<handeye::Setup> setup = handeye::ParseSetup(item);
    if (!setup) {
      throw InputError("--setup", 0, "unknown setup '" + item + "'",
                       "use eye-in-hand or eye-to-hand (or both, comma separated)");
    }
    setups.push_back(*setup);
  }
  io::CheckOutputs({{"--output", flags.output}, {"--summary", flags.summary}}, {});
  const std::vector<int> stations =
      ParseIntList("--stations", flags.stations, kMinSimulatedStations, kMaxSimulatedStations);
  const std::vector<int> outliers =
      ParseIntList("--outliers", flags.outliers, 0, kMaxSimulatedStations);
  std::vector<study::NoiseOn> noise_on;
  for (const std::string& item : SplitList("--noise-on", flags.noise_on)) {
    const std::optional<study::NoiseOn> value = study::ParseNoiseOn(item);
    if (!value) {
      throw InputError("--noise-on", 0, "unknown value '" + item + "'",
                       "use robot, camera or both");
    }
    noise_on.push_back(*value);
  }
  std::vector<sim::NoiseModel::Kind> kinds;
  for (const std::string& item : SplitList("--noise", flags.noise)) {
    const std::optional<sim::NoiseModel::Kind> kind = sim::ParseNoiseKind(item);
    if (!kind) {
      throw InputError("--noise", 0, "unknown noise kind '" + item + "'",
                       "use gaussian, uniform, systematic, student-t3 or pnp");
    }
    kinds.push_back(*kind);
  }
  const std::vector<SigmaLevel> sigmas = ParseSigmaLevels(flags.sigma);
  for (const SigmaLevel& sigma : sigmas) CheckNoiseLevel("--sigma", sigma.mm, sigma.deg);
  std::vector<double> robot_scales;
  for (const std::string& item : SplitList("--robot-scale", flags.robot_scale)) {
    char* end = nullptr;
    const double value = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0' || !(value > 0.0) || !(value <= 1000.0)) {
      throw InputError("--robot-scale", 0,
                       "'" + item + "' is not a number above 0 and at most 1000",
                       "e.g. --robot-scale 1,5");
    }
    robot_scales.push_back(value);
  }
  for (const SigmaLevel& sigma : sigmas) {
    for (double scale : robot_scales) {
      if (sigma.mm * scale > kMaxSigmaMm || sigma.deg * scale > kMaxSigmaDeg) {
        throw InputError("--robot-scale", 0,
                         "the robot noise (--sigma times --robot-scale) must stay within " +
                             std::to_string(static_cast<int>(kMaxSigmaMm)) + " mm and " +
                             std::to_string(static_cast<int>(kMaxSigmaDeg)) + " deg per axis",
                         "give a smaller --robot-scale or --sigma");
      }
    }
  }
  options.methods = ParseMethodList("--method", flags.method);
  const int trials = ParseInt("--trials", flags.trials, 1, kMaxTrials,
                              "the number of data sets per setting (e.g. 200)");
  const int threads = ParseThreads("--threads", flags.threads);
  const std::uint64_t seed = ParseSeed("--seed", flags.seed);
  const std::int64_t settings =
      std::int64_t{1} * static_cast<std::int64_t>(setups.size()) *
      static_cast<std::int64_t>(noise_on.size()) * static_cast<std::int64_t>(kinds.size()) *
      static_cast<std::int64_t>(sigmas.size()) * static_cast<std::int64_t>(stations.size()) *
      static_cast<std::int64_t>(outliers.size()) * static_cast<std::int64_t>(robot_scales.size());
  if (settings > kMaxSettings) {
    throw InputError("--stations", 0,
                     "the sweeps make " + std::to_string(settings) + " settings, more than " +
                         std::to_string(kMaxSettings),
                     "sweep fewer values of --setup, --noise-on, --noise, --sigma, --stations, "
                     "--outliers or --robot-scale");
  }
  const std::int64_t rows = settings * trials * static_cast<std::int64_t>(options.methods.size());
  if (rows > kMaxTrialRows) {
    throw InputError("--trials", 0,
                     std::to_string(settings) + " settings x " + std::to_string(trials) +
                         " trials x " + std::to_string(options.methods.size()) + " methods make " +
                         std::to_string(rows) + " trial rows, more than " +
                         std::to_string(kMaxTrialRows),
                     "give fewer --trials, methods or swept values");
  }
  if (flags.covariance != "default") {
    const auto covariance = estimation::ParseCovarianceMethod(flags.covariance);
    if (!covariance) {
      throw InputError("--covariance", 0, "unknown covariance method '" + flags.covariance + "'",
                       "use none, default, linear, unscented or montecarlo");
    }
    options.covariance.method = *covariance;
  } else {
    options.covariance.method = std::nullopt;
  }
  options.covariance.samples =
      ParseInt("--covariance-samples", flags.covariance_samples, 2, kMaxCovarianceSamples,
               "the number of Monte Carlo samples (e.g. 1000)");
  options.covariance.seed = seed;
  options.trials = trials;
  options.threads = threads;
  options.seed = seed;
  options.reject_outliers = flags.reject_outliers;
  options.estimate_noise = flags.estimate_noise;
  for (double robot_scale : robot_scales) {
    for (handeye::Setup setup : setups) {
      for (study::NoiseOn on : noise_on) {
        for (sim::NoiseModel::Kind kind : kinds) {
          for (const SigmaLevel& sigma : sigmas) {
            for (int n : stations) {
              for (int k : outliers) {
                study::Setting setting;
                setting.setup = setup;
                setting.stations = n;
                setting.noise_on = on;
                setting.noise_kind = kind;
                setting.translation_sigma = sigma.mm * 1e-3;
                setting.rotation_sigma = sigma.deg / kDeg;
                setting.gross_outliers = k;
                setting.robot_scale = robot_scale;
                options.settings.push_back(setting);
              }
            }
          }
        }
      }
    }
  }

  const study::StudyResult result = study::RunStudy(options);
  std::vector<io::OutputFile> outputs;
  if (!flags.output.empty())
    outputs.push_back({"--output", flags.output, study::TrialsCsv(result)});
  if (!flags.summary.empty()) {
    outputs.push_back({"--summary", flags.summary, study::SummaryCsv(result)});
  }
  io::WriteFilesAtomically(outputs);
  io.out << "hecal simulate: seed " << seed << "\n";
  PrintTable(result, io.out);
  if (!flags.output.empty()) io.out << "hecal: wrote per-trial errors to " << flags.output << "\n";
  if (!flags.summary.empty()) io.out << "hecal: wrote the summary to " << flags.summary << "\n";
}

void RegisterSimulateCommand(CLI::App& app, const Io& io) {
  auto flags = std::make_shared<SimulateFlags>();
  CLI::App* simulate = app.add_subcommand(
      "simulate", "The thesis study: every method on simulated data, errors and summaries");
  simulate->add_option("--setup", flags->setup, "eye-in-hand | eye-to-hand (list sweeps)")
      ->capture_default_str();
  simulate
      ->add_option("--stations", flags->stations,
                   "Stations per data set (list sweeps, 3 to 100000)")
      ->capture_default_str();
  simulate->add_option("--trials", flags->trials, "Random data sets per setting (1 to 100000)")
      ->capture_default_str();
  simulate->add_option("--noise-on", flags->noise_on, "robot | camera | both (list sweeps)")
      ->capture_default_str();
  simulate
      ->add_option("--noise", flags->noise,
                   "gaussian | uniform | systematic | student-t3 | pnp (camera) (list sweeps)")
      ->capture_default_str();
  simulate
      ->add_option("--sigma", flags->sigma,
                   "Noise levels: n (= n mm and n deg per component) or MM/DEG (list sweeps)")
      ->capture_default_str();
  simulate->add_option("--method", flags->method, "Method name(s), comma separated, or all")
      ->capture_default_str();
  simulate->add_option("--seed", flags->seed, "Random seed (0 to 2^64-1)")->capture_default_str();
  simulate->add_option("--threads", flags->threads, "Worker threads, 0 to 256 (0 = every core)")
      ->capture_default_str();
  simulate
      ->add_option("--covariance", flags->covariance,
                   "Predict X's covariance per trial and report its consistency: none | default "
                   "(each method's own) | linear | unscented | montecarlo")
      ->capture_default_str();
  simulate
      ->add_option("--covariance-samples", flags->covariance_samples,
                   "Monte Carlo samples per trial with --covariance montecarlo (2 to 100000)")
      ->capture_default_str();
  simulate
      ->add_option("--outliers", flags->outliers,
                   "Stations per data set given a random robot pose (gross outliers; list sweeps)")
      ->capture_default_str();
  simulate->add_flag("--reject-outliers", flags->reject_outliers,
                     "Every method through calibrate's outlier rejection (counts what it rejects)");
  simulate
      ->add_option("--robot-scale", flags->robot_scale,
                   "Robot noise = this times the level, camera noise = the level (list sweeps)")
      ->capture_default_str();
  simulate->add_flag("--estimate-noise", flags->estimate_noise,
                     "Tell no method the sigmas: estimated from the residuals (the default path)");
  simulate->add_option("--output", flags->output, "Per-trial CSV (written atomically)");
  simulate->add_option("--summary", flags->summary, "Summary CSV (written atomically)");
  simulate->footer(kFooter);
  simulate->callback([flags, io] { RunSimulate(*flags, io); });
}

}  // namespace hecal::cli
