// The job of `hecal pose` with every method by name: see pose_from_points.h.
#include "hecal/jobs/pose_from_points.h"

#include "hecal/core/options_check.h"

namespace hecal::jobs {
namespace {

// OpenCV's `method`, its pose finished by pose::FinishPose (refined for iterative only).
jobs::PointPoseSolver OpenCvSolver(vision::PnpMethod method) {
  return [method](const std::vector<Eigen::Vector3d>& object,
                  const std::vector<Eigen::Vector2d>& pixels, const pose::CameraModel& camera,
                  const pose::PoseOptions& pose_options) {
    const Pose T = vision::SolvePnPOpenCv(method, object, pixels, camera);
    return pose::FinishPose(std::string(vision::Info(method).name), T,
                            method == vision::PnpMethod::kIterative, object, pixels, camera,
                            pose_options.refinement);
  };
}

// `options` solving with `method`.
PointPoseOptions WithMethod(PointPoseOptions options, const AnyPoseMethod& method) {
  if (const pose::PoseMethod* core = std::get_if<pose::PoseMethod>(&method)) {
    options.method = *core;
    options.solver = nullptr;
  } else {
    options.solver = OpenCvSolver(std::get<vision::PnpMethod>(method));
  }
  return options;
}

}  // namespace

std::vector<PoseMethodEntry> PoseMethods() {
  std::vector<PoseMethodEntry> methods;
  for (const pose::PoseMethodInfo& info : pose::PoseMethods()) {
    methods.push_back({info.method, info.name, std::string(info.summary)});
  }
  for (const vision::PnpMethodInfo& info : vision::OpenCvPnpMethods()) {
    methods.push_back({info.method, info.name,
                       std::string(info.summary) + (info.method == vision::PnpMethod::kIterative
                                                        ? " (+ hecal refinement for the covariance)"
                                                        : " (no covariance)")});
  }
  return methods;
}

std::string PoseMethodNames() {
  std::string names;
  for (const PoseMethodEntry& entry : PoseMethods()) {
    names += (names.empty() ? "" : ", ") + std::string(entry.name);
  }
  return names;
}

std::optional<AnyPoseMethod> ParsePoseMethod(std::string_view name) {
  for (const PoseMethodEntry& entry : PoseMethods()) {
    if (entry.name == name) return entry.method;
  }
  return std::nullopt;
}

bool PoseFromFilesOptions::IsValid(std::string* why) const {
  return points.IsValid(why);
}

jobs::PointPoseResult EstimatePoseFromFiles(const PoseFromFilesOptions& options) {
  RequireValid(options);
  return EstimatePoseFromFiles(WithMethod(options.points, options.method));
}

}  // namespace hecal::jobs
