// `hecal plan` (docs/plan.md): the flags bound into jobs::PlanOptions (jobs/plan.h), the job run,
// the prediction printed and the planned robot poses written as a pose table.
#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <iomanip>
#include <memory>

#include "bounds.h"
#include "calibrate.h"
#include "choice_flags.h"
#include "cli.h"
#include "hecal/hecal.h"

namespace hecal::cli {
namespace {

struct PlanFlags {
  jobs::PlanOptions options;
  std::vector<std::string> existing;  // --existing ROBOT CAMERA
  int next = 0;                       // --next K (with --existing)
  double max_board_tilt_deg = 45.0;
  std::string robot_sigma, camera_sigma, goal, output;
  io::PoseWriteOptions write;
};

// "0.05deg,0.5mm": a rotation (deg|rad) and a length (mm|cm|m), in either order.
estimation::PoseSigma ParseGoal(const std::string& text) {
  const auto bad = [&] {
    return InputError("--goal", 0, "expected a rotation and a length with units, got '" + text + "'",
                      "write e.g. --goal 0.05deg,0.5mm");
  };
  const size_t comma = text.find(',');
  if (comma == std::string::npos) throw bad();
  estimation::PoseSigma goal{0.0, 0.0};
  for (const std::string& item : {text.substr(0, comma), text.substr(comma + 1)}) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (error != std::errc() || !std::isfinite(value)) throw bad();
    const std::string unit(end, item.data() + item.size());
    if (unit == "deg") goal.rotation = value * kRadiansPerDegree;
    else if (unit == "rad") goal.rotation = value;
    else if (unit == "mm") goal.translation = value * 1e-3;
    else if (unit == "cm") goal.translation = value * 1e-2;
    else if (unit == "m") goal.translation = value;
    else throw bad();
  }
  if (!(goal.rotation > 0.0 && goal.translation > 0.0)) throw bad();
  return goal;
}

void PrintSigma(std::ostream& out, const std::string& what,
                const Eigen::Matrix<double, 6, 6>& covariance) {
  const Vector6d sigma = covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
  out << std::fixed << std::setprecision(4) << what << ": rotation (" << sigma(0) * kDegreesPerRadian
      << " " << sigma(1) * kDegreesPerRadian << " " << sigma(2) * kDegreesPerRadian
      << ") deg, translation (" << sigma(3) * 1e3 << " " << sigma(4) * 1e3 << " "
      << sigma(5) * 1e3 << ") mm\n";
  out.unsetf(std::ios::floatfield);
}

void RunPlan(PlanFlags flags, const Io& io) {
  jobs::PlanOptions& options = flags.options;
  options.max_board_tilt = flags.max_board_tilt_deg * kRadiansPerDegree;
  if (!flags.robot_sigma.empty()) options.robot_sigma = ParseSigma("--robot-sigma", flags.robot_sigma);
  if (!flags.camera_sigma.empty())
    options.camera_sigma = ParseSigma("--camera-sigma", flags.camera_sigma);
  if (!flags.goal.empty()) options.goal = ParseGoal(flags.goal);
  if (!flags.existing.empty()) {
    options.existing_robot = flags.existing.at(0);
    options.existing_camera = flags.existing.at(1);
    if (flags.next < 1) {
      throw InputError("--next", 0, "--existing needs --next K: how many poses to add",
                       "give e.g. --next 3");
    }
    options.stations = flags.next;
  } else if (flags.next > 0) {
    throw InputError("--next", 0, "--next adds to an existing calibration",
                     "give --existing robot.csv camera.csv, or plan anew with --stations N");
  }
  options.read.units = flags.write.units;
  options.read.degrees = flags.write.degrees;
  RequireValid(options);
  RequireValid(flags.write);
  const jobs::PlanResult result = jobs::PlanStations(options);

  std::ostream& out = io.out;
  out << "planned " << result.T_base_gripper.size() << " station(s), "
      << handeye::SetupName(result.setup) << ", from " << result.candidates
      << " candidate poses that keep the whole target in view inside the workspace (of "
      << result.samples << " sampled)\n";
  out << "nominal X and Z: "
      << (result.nominal_from_existing ? "the existing calibration" : options.workspace) << "\n";
  out << std::setprecision(4) << "noise for the prediction: robot " << result.robot_sigma.translation * 1e3
      << " mm, " << result.robot_sigma.rotation * kDegreesPerRadian << " deg; camera "
      << result.camera_sigma.translation * 1e3 << " mm, "
      << result.camera_sigma.rotation * kDegreesPerRadian << " deg per axis"
      << (result.nominal_from_existing && !options.robot_sigma ? " (estimated)" : "") << "\n";
  if (result.before) {
    PrintSigma(out, "predicted 1σ of X now (" + std::to_string(result.existing_stations) +
                        " stations)", *result.before);
  }
  PrintSigma(out,
             "predicted 1σ of X with the plan (" +
                 std::to_string(result.existing_stations +
                                static_cast<int>(result.T_base_gripper.size())) +
                 " stations)",
             result.predicted);
  if (options.goal) {
    out << std::setprecision(4) << "goal " << options.goal->rotation * kDegreesPerRadian
        << " deg, " << options.goal->translation * 1e3 << " mm per axis: ";
    if (result.goal_stations) {
      out << "reached with " << *result.goal_stations << " stations in all\n";
    } else {
      out << "not reached with " << jobs::kMaxGoalStations
          << " stations: lower the noise (a closer board, a better robot) or the goal\n";
    }
  }
  io::PoseTable table;
  for (size_t k = 0; k < result.T_base_gripper.size(); ++k) {
    io::PoseRow row;
    row.pose = result.T_base_gripper[k];
    row.id = "plan_" + std::to_string(k + 1);
    table.rows.push_back(row);
  }
  flags.write.comments = {"hecal plan: T_base_gripper of the planned stations (docs/plan.md)"};
  io::WritePoseTable(flags.output, table, flags.write);
  out << "wrote " << flags.output << "\n";
}

}  // namespace

void RegisterPlanCommand(CLI::App& app, const Io& io) {
  auto flags = std::make_shared<PlanFlags>();
  CLI::App* command = app.add_subcommand(
      "plan", "Propose the robot poses to take: in view, in the workspace, best for X's covariance");
  AddSetupFlag(*command, flags->options.setup,
               "eye-in-hand (camera on the robot) | eye-to-hand (camera fixed)")
      ->required();
  AddWholeNumber(*command, "--stations", flags->options.stations, "How many poses to plan")
      ->capture_default_str();
  command->add_option("--target", flags->options.target, "Target file (docs/targets.md)")
      ->required();
  command->add_option("--intrinsics", flags->options.intrinsics,
                      "Camera file with the image size (docs/targets.md)")
      ->required();
  command->add_option("--workspace", flags->options.workspace,
                      "workspace.yaml: the flange's box and tilt cone, the nominal X and Z "
                      "(docs/plan.md)")
      ->required();
  command->add_option("--output", flags->output, "The planned robot poses (pose table, CSV)")
      ->required();
  command->add_option("--distance", flags->options.distance,
                      "Camera to board, metres (default: the board fills half the image width)");
  command
      ->add_option("--max-board-tilt", flags->max_board_tilt_deg,
                   "Largest angle between the view and the board's normal, degrees")
      ->capture_default_str();
  command->add_option("--robot-sigma", flags->robot_sigma,
                      "Robot noise for the prediction, MM,DEG (default 0.1,0.05)");
  command->add_option("--camera-sigma", flags->camera_sigma,
                      "Camera noise for the prediction, MM,DEG (default 0.5,0.1)");
  command->add_option("--existing", flags->existing,
                      "An existing calibration's robot and camera tables: plan what to add")
      ->expected(2);
  AddWholeNumber(*command, "--next", flags->next, "With --existing: how many poses to add");
  command->add_option("--goal", flags->goal,
                      "Wanted 1σ of X per axis, e.g. 0.05deg,0.5mm: how many stations reach it");
  AddChoice<io::RotationFormat>(*command, "--to", flags->write.rotation, io::ParseRotationFormat,
                                "rotation format", "one of " + std::string(io::RotationFormatSpellings()),
                                "Rotation form of the output (default quaternion; docs/pose-files.md)");
  AddLengthUnitFlag(*command, "--units", flags->write.units,
                    "Length unit of the output and of --existing's columns without a suffix (default m)");
  command->add_flag("--degrees", flags->write.degrees, "Output angles in degrees");
  AddSeedFlag(*command, flags->options.seed);
  command->callback([flags, io] { RunPlan(*flags, io); });
}

}  // namespace hecal::cli
