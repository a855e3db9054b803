// `hecal pivot --robot poses.csv` (docs/pivot.md, docs/cli.md#hecal-pivot): tool-centre-point
// calibration by pivoting. The flags bound into jobs::PivotFileOptions (jobs/pivot.h: the table
// read, estimation::CalibratePivot); the summary printed (report/pivot_text.h), the result file
// written (report/pivot_file.h).
#include <CLI/CLI.hpp>
#include <memory>

#include "calibrate.h"
#include "cli.h"
#include "hecal/hecal.h"
#include "pose_read_flags.h"

namespace hecal::cli {
namespace {

struct PivotFlags {
  jobs::PivotFileOptions options;
  std::string robot_sigma;  // --robot-sigma MM,DEG
  bool keep_outliers = false;
  std::string output;
};

void RunPivot(const PivotFlags& flags, const Io& io) {
  jobs::PivotFileOptions options = flags.options;
  if (!flags.robot_sigma.empty())
    options.pivot.sigma = ParseSigma("--robot-sigma", flags.robot_sigma);
  options.pivot.reject_outliers = !flags.keep_outliers;
  RequireValid(options);
  io::CheckOutputs({{"--output", flags.output}}, {{"--robot", options.robot}});
  const report::PivotDocument document = jobs::CalibratePivotFile(options);
  report::PrintPivotSummary(io.out, document);
  if (!flags.output.empty()) {
    report::WritePivotResult(flags.output, document);
    io.out << "wrote " << flags.output << "\n";
  }
}

}  // namespace

void RegisterPivotCommand(CLI::App& app, const Io& io) {
  auto flags = std::make_shared<PivotFlags>();
  CLI::App* command = app.add_subcommand(
      "pivot",
      "Tool-centre-point calibration: the tip in the flange and the pivot in the base "
      "from robot poses pivoting about one point");
  command
      ->add_option("--robot", flags->options.robot,
                   "Robot poses T_base_flange, one per orientation (docs/pose-files.md)")
      ->required();
  command->add_option("--robot-sigma", flags->robot_sigma,
                      "Robot pose noise per axis, MM,DEG (estimated when absent)");
  command->add_option("--output", flags->output, "Result file (.json, or .yaml/.yml)");
  command->add_flag("--keep-outliers", flags->keep_outliers,
                    "Use every station: flag outliers but do not leave them out");
  AddRobotReadFlags(*command, flags->options.read, "", "T_flange_base");
  command->footer(
      "Model: R_i t_tip + t_i = p (docs/pivot.md). Tilt the tool about two axes, 10 to 30 deg\n"
      "either way, 10 or more orientations. Degenerate data (too little rotation, one axis only)\n"
      "exit 2 naming what cannot be observed.");
  command->callback([flags, &io] { RunPivot(*flags, io); });
}

}  // namespace hecal::cli
