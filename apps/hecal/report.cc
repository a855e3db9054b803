// `hecal report RESULT.json --output report.html [--robot robot.csv …] [--images DIR]`: the
// interactive HTML page of a calibration result (docs/report.md, docs/cli.md#report);
// jobs::WriteCalibrationReport.
#include <CLI/CLI.hpp>
#include <memory>

#include "choice_flags.h"
#include "cli.h"
#include "hecal/hecal.h"

namespace hecal::cli {

void RegisterReportCommand(CLI::App& app, const Io& io) {
  auto options = std::make_shared<jobs::CalibrationReportOptions>();
  CLI::App* command = app.add_subcommand(
      "report", "Write the interactive HTML page of a calibration result (opens offline)");
  command
      ->add_option("RESULT", options->result,
                   "Result file of `hecal calibrate --output` (JSON; also of --method global)")
      ->required();
  command->add_option("--output", options->output, "The page, e.g. report.html")->required();
  command->add_option("--robot", options->robot,
                      "The robot poses the result was calibrated from, for the 3D scene");
  command->add_option("--images", options->images,
                      "The image folder of a result of calibrate --images, for the thumbnails");
  AddLengthUnitFlag(*command, "--units", options->robot_read.units,
                    "With --robot: length unit of columns without a suffix (m or mm)");
  command->add_flag("--degrees", options->robot_read.degrees,
                    "With --robot: angles without a suffix are in degrees");
  AddEulerFlag(*command, "--euler", options->robot_read.euler,
               "With --robot: Euler sequence of a1,a2,a3 columns");
  command->add_flag("--robot-inverse", options->robot_read.invert,
                    "With --robot: the file holds T_gripper_base");
  command->callback([options, io] {
    io::CheckOutputs({{"--output", options->output}},
                     {{"RESULT", options->result}, {"--robot", options->robot}});
    jobs::WriteCalibrationReport(*options);
    io.out << "wrote " << options->output << "\n";
  });
}

}  // namespace hecal::cli
