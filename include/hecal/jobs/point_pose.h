// The job of `hecal pose` (docs/pose-from-points.md, docs/cli.md): the camera pose
// T_camera_target from a file of object points and a file of their pixels.
//
// Inputs
//   points        io/point_file.h, header `id,x,y,z` (id optional). Lengths: a suffix on all
//                 three columns (x_mm or x_m) wins over `units`.
//   image_points  header `id,u,v` (id optional), pixels with the origin at the centre of the
//                 top-left pixel (OpenCV's convention).
//   Pairing: by id when both files have ids (every image id must name an object point; object
//   points without an image point are left out), otherwise by order (equal counts).
//   Camera: `intrinsics` (io/camera_file.h), or the distortion-free pinhole X = F x/z of `focal`
//   (px) with the principal point `principal_point` (default 0,0) — exactly one of the two.
// Method: pose::EstimatePose's `method` (pose/pose_method.h), or `solver` when set (the vision
// layer's OpenCV PnP methods, vision/opencv_pnp.h, which this layer cannot see; every method by
// name: jobs/pose_from_points.h).
// Bounds (IsValid): exactly one of focal and intrinsics; focal positive and finite; a principal
// point only with focal, finite; pixel_sigma above 0 and at most 100 px. A bad value names the
// field ("PointPoseOptions.focal", core/options_check.h).
// Errors: InputError with file:line for bad files and for a pixel without a ray in the camera,
// DegenerateError when the method cannot determine the pose from these points.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hecal/io/units.h"
#include "hecal/pose/camera_model.h"
#include "hecal/pose/pose_method.h"

namespace hecal::jobs {

// A pose solver outside the pose layer: object points (metres, target frame), their pixels, the
// camera and the options (refinement σ) → the estimate.
using PointPoseSolver = std::function<pose::PoseEstimate(
    const std::vector<Eigen::Vector3d>&, const std::vector<Eigen::Vector2d>&,
    const pose::CameraModel&, const pose::PoseOptions&)>;

struct PointPoseOptions {
  static constexpr double kMaxPixelSigma = 100.0;  // px

  std::string points;                              // object points file
  std::string image_points;                        // image points file
  std::string intrinsics;                          // camera file; "" = the pinhole of `focal`
  std::optional<double> focal;                     // px
  std::optional<Eigen::Vector2d> principal_point;  // px, with focal; nullopt = (0, 0)
  pose::PoseMethod method = pose::PoseMethod::kLinear;
  PointPoseSolver solver;                         // used instead of `method` when set
  std::optional<double> pixel_sigma;              // px; nullopt = estimated from the residuals
  io::LengthUnit units = io::LengthUnit::kMetre;  // object columns without a suffix

  // True when usable (above); else false with "PointPoseOptions.<field>: problem (fix: …)".
  bool IsValid(std::string* why) const;
};

struct PointPoseResult {
  pose::PoseEstimate estimate;
  std::vector<std::optional<std::string>> point_ids;  // the image point of each pair
  io::LengthUnit unit = io::LengthUnit::kMetre;       // of the object file
  std::vector<std::string> camera_notes;              // from the camera file
  std::size_t points = 0;                             // pairs used
};

// Reads both files and the camera, pairs the points and solves; throws hecal::InputError when
// !options.IsValid or for bad files, DegenerateError when the pose is undetermined.
PointPoseResult EstimatePoseFromFiles(const PointPoseOptions& options);

}  // namespace hecal::jobs
