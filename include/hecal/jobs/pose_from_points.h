// The job of `hecal pose` with every pose method by name (docs/pose-from-points.md, docs/cli.md#
// hecal-pose): the one list of the methods `hecal pose --method NAME` accepts, and the solver of
// each, for callers that choose a method by its name.
//
// Methods, in this order (PoseMethods):
//   the pose layer's (pose/pose_method.h: linear, linear-raw, dlt), solved by pose::EstimatePose;
//   OpenCV's solvePnP methods (vision/opencv_pnp.h: ippe, sqpnp, epnp, iterative), their pose
//   finished by pose::FinishPose: iterative is followed by hecal's reprojection refinement (it
//   has a covariance), the closed forms are not (their residuals and RMS only, no covariance).
//
// Steps (EstimatePoseFromFiles)
//   1. The options checked (IsValid) before any file is read: the method name first, then the
//      files, camera and σ (report::PointPoseOptions::IsValid, report/point_pose.h).
//   2. The method's solver put into a copy of `points` (its `method`, or its `solver` for
//      OpenCV's methods; whatever `points` held there is replaced).
//   3. report::EstimatePoseFromFiles: both point files read and paired, the camera read, solved.
// Frames and units: T_camera_target (x_camera = T · P), the object file's length unit; pixels
// with the origin at the centre of the top-left pixel (report/point_pose.h).
//
// Errors (hecal::InputError): an unknown method ("PoseFromFilesOptions.method", with the list of
// names), the fields of report::PointPoseOptions ("PointPoseOptions.focal", ...), bad files;
// OpenCV's preconditions (source "PnpMethod NAME", vision/opencv_pnp.h); DegenerateError when
// the method cannot determine the pose from these points. Nothing is written.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "hecal/report/point_pose.h"

namespace hecal::jobs {

struct PoseMethodEntry {
  std::string_view name;  // what `method` accepts, e.g. "linear", "ippe"
  std::string help;       // one line: what it is, when to use it, whether it has a covariance
};

// Every method, in the order above (the order `hecal pose --help` lists them).
std::vector<PoseMethodEntry> PoseMethods();

// Every method name, comma separated ("linear, linear-raw, dlt, ippe, ...").
std::string PoseMethodNames();

struct PoseFromFilesOptions {
  // Files, camera, σ and units; its `method` and `solver` are set by the job from `method`.
  report::PointPoseOptions points;
  std::string method = "linear";  // a name of PoseMethods()

  // core/options_check.h: false naming the first bad field: PoseFromFilesOptions.method (not a
  // name of PoseMethods()), then those of PointPoseOptions::IsValid.
  bool IsValid(std::string* why) const;
};

// Steps 1–3 above.
report::PointPoseResult EstimatePoseFromFiles(const PoseFromFilesOptions& options);

}  // namespace hecal::jobs
