// The job of `hecal pose` with every pose method (docs/pose-from-points.md and
// docs/cli.md#hecal-pose): the one list of the methods `hecal pose --method NAME` accepts, each
// with its name and help line, and the solver of each.
//
// Methods, in this order (PoseMethods):
//   the pose layer's (pose/pose_method.h: linear, linear-raw, dlt), solved by pose::EstimatePose;
//   OpenCV's solvePnP methods (vision/opencv_pnp.h: ippe, sqpnp, epnp, iterative), their pose
//   finished by pose::FinishPose: iterative is followed by hecal's reprojection refinement (it
//   has a covariance), the closed forms are not (their residuals and RMS only, no covariance).
//
// Steps (EstimatePoseFromFiles)
//   1. The options checked (IsValid: the files, camera and σ of PointPoseOptions::IsValid,
//      jobs/point_pose.h) before any file is read.
//   2. The method's solver put into a copy of `points` (its `method`, or its `solver` for
//      OpenCV's methods; whatever `points` held there is replaced).
//   3. EstimatePoseFromFiles: both point files read and paired, the camera read, solved.
// Frames and units: T_camera_target (x_camera = T · P), the object file's length unit; pixels
// with the origin at the centre of the top-left pixel (jobs/point_pose.h).
//
// Errors (hecal::InputError): the fields of PointPoseOptions ("PointPoseOptions.focal",
// ...), bad files; OpenCV's preconditions (source "PnpMethod NAME", vision/opencv_pnp.h);
// DegenerateError when the method cannot determine the pose from these points. Nothing is
// written. A name that is no method is the caller's to refuse (ParsePoseMethod returns nullopt;
// the list of names for its message is PoseMethodNames).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "hecal/pose/pose_method.h"
#include "hecal/jobs/point_pose.h"
#include "hecal/vision/opencv_pnp.h"

namespace hecal::jobs {

// A method of either layer.
using AnyPoseMethod = std::variant<pose::PoseMethod, vision::PnpMethod>;

struct PoseMethodEntry {
  AnyPoseMethod method;
  std::string_view name;  // e.g. "linear", "ippe"
  std::string help;       // one line: what it is, when to use it, whether it has a covariance
};

// Every method, in the order above (the order `hecal pose --help` lists them).
std::vector<PoseMethodEntry> PoseMethods();

// Every method name, comma separated ("linear, linear-raw, dlt, ippe, ...").
std::string PoseMethodNames();

// The method called `name` (exactly, as PoseMethods spells it); nullopt for any other text.
std::optional<AnyPoseMethod> ParsePoseMethod(std::string_view name);

struct PoseFromFilesOptions {
  // Files, camera, σ and units; its `method` and `solver` are set by the job from `method`.
  PointPoseOptions points;
  AnyPoseMethod method = pose::PoseMethod::kLinear;

  // core/options_check.h: false naming the first bad field of PointPoseOptions::IsValid (every
  // method is valid).
  bool IsValid(std::string* why) const;
};

// Steps 1–3 above.
jobs::PointPoseResult EstimatePoseFromFiles(const PoseFromFilesOptions& options);

}  // namespace hecal::jobs
