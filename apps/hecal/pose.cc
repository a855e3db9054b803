// `hecal pose` (docs/cli.md#hecal-pose, docs/pose-from-points.md): binds the flags into
// jobs::PoseFromFilesOptions (jobs/pose_from_points.h: every method, by name; its IsValid names
// fields, shown as flags by field_flags.h), runs the job, prints the pose and writes its JSON
// (report/pose_file.h). Built without the vision layer, the command runs report's job
// (jobs/point_pose.h) with the pose layer's methods and refuses OpenCV's by name.
#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bounds.h"
#include "choice_flags.h"
#include "cli.h"
#include "hecal/hecal.h"
#include "list_flags.h"
#if defined(HECAL_HAVE_OPENCV_PEERS)
#else
#include <algorithm>
#include <array>
#include <string_view>

#endif

namespace hecal::cli {
namespace {

#if defined(HECAL_HAVE_OPENCV_PEERS)
using PoseOptions = jobs::PoseFromFilesOptions;

jobs::PointPoseOptions& PointOptions(PoseOptions& options) {
  return options.points;
}

std::vector<std::pair<std::string, std::string>> MethodHelp() {
  std::vector<std::pair<std::string, std::string>> lines;
  for (const jobs::PoseMethodEntry& entry : jobs::PoseMethods()) {
    lines.emplace_back(entry.name, entry.help);
  }
  return lines;
}

std::string MethodList() {
  return jobs::PoseMethodNames();
}

void SetMethod(const std::string& method, PoseOptions& options) {
  options.method =
      ParseChoice("--method", method, jobs::ParsePoseMethod, "method", "one of " + MethodList());
}

jobs::PointPoseResult EstimatePose(const PoseOptions& options) {
  return jobs::EstimatePoseFromFiles(options);
}
#else
// Without the vision layer: the pose layer's methods; OpenCV's are refused by name.
using PoseOptions = jobs::PointPoseOptions;

jobs::PointPoseOptions& PointOptions(PoseOptions& options) {
  return options;
}

std::vector<std::pair<std::string, std::string>> MethodHelp() {
  std::vector<std::pair<std::string, std::string>> lines;
  for (const pose::PoseMethodInfo& info : pose::PoseMethods()) {
    lines.emplace_back(info.name, info.summary);
  }
  return lines;
}

std::string MethodList() {
  std::string names;
  for (const auto& [name, help] : MethodHelp()) names += (names.empty() ? "" : ", ") + name;
  return names;
}

void SetMethod(const std::string& method, PoseOptions& options) {
  if (const std::optional<pose::PoseMethod> core = pose::ParsePoseMethod(method)) {
    options.method = *core;
    return;
  }
  constexpr std::array<std::string_view, 4> kVisionMethods = {"ippe", "sqpnp", "epnp", "iterative"};
  if (std::find(kVisionMethods.begin(), kVisionMethods.end(), method) != kVisionMethods.end()) {
    throw InputError("--method", 0, "--method " + method + " needs the vision layer (OpenCV)",
                     "rebuild with -DHECAL_BUILD_VISION=ON, or use one of " + MethodList());
  }
  throw InputError("--method", 0, "unknown method '" + method + "'", "use one of " + MethodList());
}

jobs::PointPoseResult EstimatePose(const PoseOptions& options) {
  return jobs::EstimatePoseFromFiles(options);
}
#endif

struct PoseCommand {
  PoseOptions options;
  std::string output;
};

void RunPose(PoseCommand& command, const Io& io) {
  RequireValid(command.options);
  const jobs::PointPoseOptions& points = PointOptions(command.options);
  io::CheckOutputs({{"--output", command.output}}, {{"--points", points.points},
                                                    {"--image-points", points.image_points},
                                                    {"--intrinsics", points.intrinsics}});
  const jobs::PointPoseResult result = EstimatePose(command.options);
  for (const std::string& note : result.camera_notes) io.out << "note: " << note << "\n";
  for (const std::string& warning : result.estimate.warnings) {
    io.err << "hecal: warning: " << warning << "\n";
  }
  report::PrintPoseEstimate(io.out, result.estimate, result.points, result.unit);
  if (!command.output.empty()) {
    io::WriteFileAtomically(command.output,
                            report::PoseResultJson(result.estimate, result.point_ids, result.unit));
    io.out << "wrote " << command.output << "\n";
  }
}

}  // namespace

void RegisterPoseCommand(CLI::App& app, const Io& io) {
  auto pose_command = std::make_shared<PoseCommand>();
  PoseOptions& options = pose_command->options;
  jobs::PointPoseOptions& o = PointOptions(options);
  CLI::App* command = app.add_subcommand(
      "pose", "Camera pose T_camera_target from known object points and their pixels");
  command->add_option("--points", o.points, "Object points: CSV id,x,y,z (target frame)")
      ->required();
  command->add_option("--image-points", o.image_points, "Image points: CSV id,u,v (px)")
      ->required();
  command->add_option_function<double>(
      "--focal", [&o](double focal) { o.focal = focal; },
      "Focal length F (px) of a distortion-free pinhole (docs/pose-from-points.md)");
  command->add_option_function<std::string>(
      "--principal-point",
      [&o](const std::string& text) {
        const std::vector<double> c = ParseNumberList("--principal-point", text, 2, "CX,CY (px)");
        o.principal_point = Eigen::Vector2d(c[0], c[1]);
      },
      "CX,CY (px) with --focal (default 0,0)");
  command->add_option(
      "--intrinsics", o.intrinsics,
      "camera.yaml (hecal, OpenCV or ROS layout; plumb_bob distortion) or ViSP camera "
      "XML");
  command->add_option_function<std::string>(
      "--method", [&options](const std::string& text) { SetMethod(text, options); },
      "Method (default linear): " + MethodList());
  command->add_option_function<double>(
      "--pixel-sigma", [&o](double sigma) { o.pixel_sigma = sigma; },
      "Pixel noise σ (px) for the covariance (default: from the residuals)");
  AddLengthUnitFlag(*command, "--units", o.units,
                    "Length unit of object columns without a suffix: m (default) or mm");
  command->add_option("--output", pose_command->output, "Result JSON (written atomically)");
  std::string footer = "Methods:\n";
  for (const auto& [name, help] : MethodHelp()) footer += "  " + name + ": " + help + "\n";
  footer +=
      "Pairing: by id when both files have an id column, else by order.\n"
      "Output: R, t (object file's unit), rotation vector, 1σ per component (refined methods:\n"
      "  right perturbation, (rx,ry,rz,tx,ty,tz)), RMS reprojection error (px).";
  command->footer(footer);
  command->callback([pose_command, io] { RunPose(*pose_command, io); });
}

}  // namespace hecal::cli
