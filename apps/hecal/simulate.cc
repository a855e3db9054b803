// `hecal simulate` (docs/cli.md#hecal-simulate, docs/thesis-study.md): binds the flags into
// jobs::SimulateOptions (jobs/simulate.h; list flags parsed once here, ranges checked by its
// IsValid), runs jobs::Simulate, prints a table per setting (report/study_text.h) and writes the
// CSV files of study/study_csv.h and the HTML page (report/simulate_page.h), all or none.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>

#include "bounds.h"
#include "cli.h"
#include "hecal/hecal.h"
#include "list_flags.h"
#include "simulate_pivot.h"
#include "simulate_streams.h"

namespace hecal::cli {
namespace {

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
Same --seed, same CSV files whatever --threads.
--pivot: the pivot study instead (docs/pivot.md): --sigma, --stations, --trials and --seed
  (defaults 0.1, 20, 200), RMSE, NEES and coverage of hecal pivot's fit.)";

struct SimulateCommand {
  jobs::SimulateOptions options;
  std::string output;
  std::string summary;
  std::string report;
  StreamStudyFlags streams;  // --streams and its flags
  PivotStudyFlags pivot;     // --pivot and its flags
  bool stations_given = false;
  bool trials_given = false;
};

void RunSimulate(const SimulateCommand& command, const Io& io) {
  if (command.pivot.pivot) {
    const std::pair<const char*, bool> other[] = {{"--streams", command.streams.streams},
                                                  {"--output", !command.output.empty()},
                                                  {"--summary", !command.summary.empty()},
                                                  {"--report", !command.report.empty()}};
    for (const auto& [flag, given] : other) {
      if (given) {
        throw InputError(flag, 0, std::string(flag) + " does not apply to the pivot study",
                         "leave it out with --pivot (--write-pivot writes a pose file)");
      }
    }
    return RunSimulatePivot({command.options, command.streams.sigma_given, command.stations_given,
                             command.trials_given},
                            command.pivot, io);
  }
  if (command.streams.streams) {
    if (!command.report.empty()) {
      throw InputError("--report", 0, "--report has no page for the stream study",
                       "leave --report out with --streams");
    }
    return RunSimulateStreams(command.options, command.streams, command.output, command.summary,
                              io);
  }
  RequireValid(command.options);  // before the output paths are checked
  io::CheckOutputs(
      {{"--output", command.output}, {"--summary", command.summary}, {"--report", command.report}},
      {});
  const study::StudyResult result = jobs::Simulate(command.options);
  std::vector<io::OutputFile> outputs;
  if (!command.output.empty())
    outputs.push_back({"--output", command.output, study::TrialsCsv(result)});
  if (!command.summary.empty()) {
    outputs.push_back({"--summary", command.summary, study::SummaryCsv(result)});
  }
  if (!command.report.empty()) {
    const std::string title = std::filesystem::path(command.report).filename().string();
    outputs.push_back({"--report", command.report,
                       report::FormatHtmlPage(report::SimulatePageData(result, title))});
  }
  io::WriteFilesAtomically(outputs);
  io.out << "hecal simulate: seed " << command.options.seed << "\n";
  report::PrintStudyTable(io.out, result);
  if (!command.output.empty()) {
    io.out << "hecal: wrote per-trial errors to " << command.output << "\n";
  }
  if (!command.summary.empty()) {
    io.out << "hecal: wrote the summary to " << command.summary << "\n";
  }
  if (!command.report.empty()) io.out << "hecal: wrote the page to " << command.report << "\n";
}

}  // namespace

void RegisterSimulateCommand(CLI::App& app, const Io& io) {
  auto command = std::make_shared<SimulateCommand>();
  jobs::SimulateOptions& o = command->options;
  CLI::App* simulate = app.add_subcommand(
      "simulate", "The thesis study: every method on simulated data, errors and summaries");
  simulate
      ->add_option_function<std::string>(
          "--setup",
          [&o](const std::string& text) {
            o.setups = ParseChoiceList("--setup", text, handeye::ParseSetup, "setup",
                                       "eye-in-hand or eye-to-hand (or both, comma separated)");
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
            o.noise_on = ParseChoiceList("--noise-on", text, study::ParseNoiseOn, "value",
                                         "robot, camera or both");
          },
          "robot | camera | both (list sweeps)")
      ->default_str("both");
  simulate
      ->add_option_function<std::string>(
          "--noise",
          [&o](const std::string& text) {
            o.noise = ParseChoiceList("--noise", text, sim::ParseNoiseKind, "noise kind",
                                      "gaussian, uniform, systematic, student-t3 or pnp");
          },
          "gaussian | uniform | systematic | student-t3 | pnp (camera) (list sweeps)")
      ->default_str("gaussian");
  simulate
      ->add_option_function<std::string>(
          "--sigma",
          [&o, command](const std::string& text) {
            o.sigmas = ParseNoiseLevels("--sigma", text);
            command->streams.sigma_given = true;
          },
          "Noise levels: n (= n mm and n deg per component) or MM/DEG (list sweeps)")
      ->default_str("0,0.3,1");
  AddMethodListFlag(*simulate, o.methods);
  AddSeedFlag(*simulate, o.seed);
  AddWholeNumber(*simulate, "--threads", o.threads, "Worker threads, 0 to 256 (0 = every core)")
      ->capture_default_str();
  simulate
      ->add_option_function<std::string>(
          "--covariance",
          [&o](const std::string& text) {
            using Choice = std::optional<estimation::CovarianceMethod>;
            o.covariance = ParseChoice(
                "--covariance", text,
                [](const std::string& name) -> std::optional<Choice> {
                  if (name == "default") return Choice();  // each method's own
                  const Choice method = estimation::ParseCovarianceMethod(name);
                  return method ? std::optional<Choice>(method) : std::nullopt;
                },
                "covariance method", "none, default, linear, unscented or montecarlo");
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
          [&o](const std::string& text) {
            o.robot_scales = ParseNumberList("--robot-scale", text, kAnyCount,
                                             "(robot noise over the level, e.g. 1,5)");
          },
          "Robot noise = this times the level, camera noise = the level (list sweeps)")
      ->default_str("1");
  simulate->add_flag("--estimate-noise", o.estimate_noise,
                     "Tell no method the sigmas: estimated from the residuals (the default path)");
  simulate->add_option("--output", command->output, "Per-trial CSV (written atomically)");
  simulate->add_option("--summary", command->summary, "Summary CSV (written atomically)");
  simulate->add_option("--report", command->report,
                       "HTML page of the results with figures (docs/report.md; opens offline)");
  AddStreamStudyFlags(*simulate, command->streams);
  simulate->footer(kFooter);
  AddPivotStudyFlags(*simulate, command->pivot);
  simulate->callback([command, io, simulate] {
    command->stations_given = simulate->count("--stations") > 0;
    command->trials_given = simulate->count("--trials") > 0;
    RunSimulate(*command, io);
  });
}

}  // namespace hecal::cli
