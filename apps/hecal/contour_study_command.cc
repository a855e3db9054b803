// `hecal contour study` (docs/cli.md#hecal-contour-study): the contour paper's experiments
// (contour/contour_study.h). The flags bind into contour::ContourStudyOptions, whose IsValid
// checks every range (field_flags.h names the flag); report/contour_study_file.h writes the CSV
// and the HTML page with the paper's Fig. 3 and 4 (--report), all or none, after the whole study
// ran.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>

#include "bounds.h"
#include "choice_flags.h"
#include "contour.h"
#include "hecal/hecal.h"

namespace hecal::cli {
namespace {

// Monte Carlo poses kept for the page's Fig. 4 (of --samples per step).
constexpr int kPlottedSamples = 1000;

struct StudyCommand {
  contour::ContourStudyOptions options;
  std::string contour;  // --contour: the target's control points, read into options.target
  std::string output, report;
  std::optional<double> covariance_at;
};

void RunStudy(StudyCommand command, const Io& io) {
  contour::ContourStudyOptions& o = command.options;
  if (!command.contour.empty()) o.target = io::ReadContourFile(command.contour);
  if (!command.report.empty()) o.keep_samples = kPlottedSamples;
  RequireValid(o);
  io::CheckOutputs({{"--output", command.output}, {"--report", command.report}},
                   {{"--contour", command.contour}});

  const std::vector<contour::StudyStep> steps = contour::RunContourStudy(o);
  report::PrintContourStudy(io.out, o, steps);

  std::vector<io::OutputFile> outputs;
  if (!command.output.empty()) {
    outputs.push_back({"--output", command.output, report::ContourStudyCsv(o, steps)});
  }
  if (!command.report.empty()) {
    const std::string title = std::filesystem::path(command.report).filename().string();
    outputs.push_back({"--report", command.report,
                       report::FormatHtmlPage(report::ContourStudyPageData(
                           o, steps, command.covariance_at.value_or(o.from), title))});
  }
  io::WriteFilesAtomically(outputs);
  for (const std::string& file : {command.output, command.report}) {
    if (!file.empty()) io.out << "wrote " << file << "\n";
  }
}

}  // namespace

void AddContourStudyCommand(CLI::App& contour, const Io& io) {
  auto command = std::make_shared<StudyCommand>();
  contour::ContourStudyOptions& o = command->options;
  CLI::App* study = contour.add_subcommand("study",
                                           "The contour paper's experiments: UT vs Monte Carlo "
                                           "along one motion (docs/contour.md#the-experiments)");
  AddChoice<contour::StudyMotion>(*study, "--motion", o.motion, contour::ParseStudyMotion, "motion",
                                  "one of tx, ty, tz, rx, ry, rz", "tx|ty|tz|rx|ry|rz")
      ->required();
  study->add_option("--from", o.from, "First value (mm or degrees)")->required();
  study->add_option("--to", o.to, "Last value (mm or degrees)")->required();
  AddWholeNumber(*study, "--steps", o.steps, "Number of values from --from to --to (1 to 10000)")
      ->required();
  study->add_option("--pixel-noise", o.pixel_noise, "σ per image coordinate, px (0.5; 0 to 100)");
  study->add_option("--z0", o.z0_mm, "Initial distance, mm (5000)");
  study->add_option("--focal", o.focal_mm, "Focal length, mm (50)");
  study->add_option("--pixel-size", o.pixel_size_mm, "Pixel size, mm (0.0083)");
  study->add_option("--contour", command->contour,
                    "Target control points, CSV x,y in mm on the target plane (default: built in)");
  AddWholeNumber(*study, "--samples", o.samples,
                 "Monte Carlo samples per step (5000; 2 to 1000000)");
  AddWholeNumber(*study, "--seed", o.seed, "Random seed (1; 0 to 2^64-1)");
  AddWholeNumber(*study, "--threads", o.threads, "Threads, 0 to 256 (0: every core)");
  study->add_option_function<double>(
      "--ut-w0",
      [&o](double w0) { o.unscented.unscented = uncertainty::UnscentedParameters::Symmetric(w0); },
      "UT centre weight w0 (0)");
  study->add_option("--output", command->output,
                    "CSV: motion,value,component,mc_mean_error,mc_std,ut_mean_error,ut_std,bias");
  study->add_option("--report", command->report,
                    "HTML page: the numbers, the paper's Fig. 3 and Fig. 4 (docs/report.md)");
  study->add_option_function<double>(
      "--covariance-at", [command](double at) { command->covariance_at = at; },
      "Motion value of the page's Fig. 4 (default: --from)");
  study->callback([command, io] { RunStudy(*command, io); });
}

}  // namespace hecal::cli
