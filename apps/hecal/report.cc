// `hecal report RESULT.json --output report.html [--robot robot.csv …] [--images DIR]`: the
// interactive HTML page of a calibration result (docs/report.md, docs/cli.md#report);
// jobs::WriteCalibrationReport.
#include <CLI/CLI.hpp>
#include <memory>

#include "cli.h"
#include "hecal/hecal.h"
#include "pose_read_flags.h"

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
  AddRobotReadFlags(*command, options->robot_read, "With --robot: ", "T_gripper_base");
  command->callback([options, io] {
    io::CheckOutputs({{"--output", options->output}},
                     {{"RESULT", options->result}, {"--robot", options->robot}});
    jobs::WriteCalibrationReport(*options);
    io.out << "wrote " << options->output << "\n";
  });
}

}  // namespace hecal::cli
