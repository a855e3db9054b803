// `hecal pose` (docs/cli.md#hecal-pose, docs/pose-from-points.md): binds the flags into
// report::PointPoseOptions (report/point_pose.h; its IsValid names fields, shown as flags by
// field_flags.h), runs the job, prints the pose and writes its JSON (report/pose_file.h).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "cli.h"
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/io/atomic_file.h"
#include "hecal/io/units.h"
#include "hecal/pose/pose_method.h"
#include "hecal/report/point_pose.h"
#include "hecal/report/pose_file.h"
#include "hecal/report/pose_text.h"
#if defined(HECAL_HAVE_OPENCV_PEERS)
#include "hecal/vision/opencv_pnp.h"
#endif

namespace hecal::cli {
namespace {

// --principal-point CX,CY (px).
Eigen::Vector2d ParsePrincipalPoint(const std::string& text) {
  const std::size_t comma = text.find(',');
  double c[2] = {0.0, 0.0};
  bool ok = comma != std::string::npos;
  for (int k = 0; ok && k < 2; ++k) {
    const std::string part = k == 0 ? text.substr(0, comma) : text.substr(comma + 1);
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), c[k]);
    ok = error == std::errc() && end == part.data() + part.size() && std::isfinite(c[k]);
  }
  if (!ok) {
    throw InputError("--principal-point", 0, "expected two numbers CX,CY, got '" + text + "'",
                     "write e.g. --principal-point 640,480 (pixels)");
  }
  return {c[0], c[1]};
}

// ---- methods -----------------------------------------------------------------------------------

std::string MethodList() {
  std::string names;
  for (const pose::PoseMethodInfo& info : pose::PoseMethods()) {
    names += (names.empty() ? "" : ", ") + std::string(info.name);
  }
#if defined(HECAL_HAVE_OPENCV_PEERS)
  for (const vision::PnpMethodInfo& info : vision::OpenCvPnpMethods()) {
    names += ", " + std::string(info.name);
  }
#endif
  return names;
}

// --method NAME into the options: one of the pose layer's methods, or (with the vision layer)
// OpenCV's PnP finished by pose::FinishPose.
void SetMethod(const std::string& method, report::PointPoseOptions& options) {
  if (const std::optional<pose::PoseMethod> core = pose::ParsePoseMethod(method)) {
    options.method = *core;
    options.solver = nullptr;
    return;
  }
#if defined(HECAL_HAVE_OPENCV_PEERS)
  if (const std::optional<vision::PnpMethod> peer = vision::ParsePnpMethod(method)) {
    options.solver = [method, peer = *peer](const std::vector<Eigen::Vector3d>& object,
                                            const std::vector<Eigen::Vector2d>& pixels,
                                            const pose::CameraModel& camera,
                                            const pose::PoseOptions& pose_options) {
      const Pose T = vision::SolvePnPOpenCv(peer, object, pixels, camera);
      return pose::FinishPose(method, T, peer == vision::PnpMethod::kIterative, object, pixels,
                              camera, pose_options.refinement);
    };
    return;
  }
#else
  constexpr std::array<std::string_view, 4> kVisionMethods = {"ippe", "sqpnp", "epnp", "iterative"};
  if (std::find(kVisionMethods.begin(), kVisionMethods.end(), method) != kVisionMethods.end()) {
    throw InputError("--method", 0, "--method " + method + " needs the vision layer (OpenCV)",
                     "rebuild with -DHECAL_BUILD_VISION=ON, or use one of " + MethodList());
  }
#endif
  throw InputError("--method", 0, "unknown method '" + method + "'", "use one of " + MethodList());
}

struct PoseCommand {
  report::PointPoseOptions options;
  std::string output;
};

void RunPose(const PoseCommand& command, const Io& io) {
  const report::PointPoseOptions& options = command.options;
  std::string why;
  if (!options.IsValid(&why)) throw OptionsError(why);
  io::CheckOutputs({{"--output", command.output}}, {{"--points", options.points},
                                                    {"--image-points", options.image_points},
                                                    {"--intrinsics", options.intrinsics}});
  const report::PointPoseResult result = report::EstimatePoseFromFiles(options);
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
  report::PointPoseOptions& o = pose_command->options;
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
      [&o](const std::string& text) { o.principal_point = ParsePrincipalPoint(text); },
      "CX,CY (px) with --focal (default 0,0)");
  command->add_option(
      "--intrinsics", o.intrinsics,
      "camera.yaml (hecal, OpenCV or ROS layout; plumb_bob distortion) or ViSP camera "
      "XML");
  command->add_option_function<std::string>(
      "--method", [&o](const std::string& text) { SetMethod(text, o); },
      "Method (default linear): " + MethodList());
  command->add_option_function<double>(
      "--pixel-sigma", [&o](double sigma) { o.pixel_sigma = sigma; },
      "Pixel noise σ (px) for the covariance (default: from the residuals)");
  command->add_option_function<std::string>(
      "--units",
      [&o](const std::string& text) {
        const std::optional<io::LengthUnit> unit = io::ParseLengthUnit(text);
        if (!unit) throw InputError("--units", 0, "unknown unit '" + text + "'", "use m or mm");
        o.units = *unit;
      },
      "Length unit of object columns without a suffix: m (default) or mm");
  command->add_option("--output", pose_command->output, "Result JSON (written atomically)");
  std::string footer = "Methods:\n";
  for (const pose::PoseMethodInfo& info : pose::PoseMethods()) {
    footer += "  " + std::string(info.name) + ": " + std::string(info.summary) + "\n";
  }
#if defined(HECAL_HAVE_OPENCV_PEERS)
  for (const vision::PnpMethodInfo& info : vision::OpenCvPnpMethods()) {
    footer +=
        "  " + std::string(info.name) + ": " + std::string(info.summary) +
        (info.method == vision::PnpMethod::kIterative ? " (+ hecal refinement for the covariance)\n"
                                                      : " (no covariance)\n");
  }
#endif
  footer +=
      "Pairing: by id when both files have an id column, else by order.\n"
      "Output: R, t (object file's unit), rotation vector, 1σ per component (refined methods:\n"
      "  right perturbation, (rx,ry,rz,tx,ty,tz)), RMS reprojection error (px).";
  command->footer(footer);
  command->callback([pose_command, io] { RunPose(*pose_command, io); });
}

}  // namespace hecal::cli
