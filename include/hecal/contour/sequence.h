// Camera motion along an image sequence, and synthetic sequences of known motion: the jobs of
// `hecal contour track` and `hecal contour render` (docs/contour.md), in the contour layer
// (Eigen only; the images are read and written by vision/contour_images.h).
//
// SequenceTracker: the shape-space Kalman filter (shape_tracker.h) over the frames, and every
// shape vector S = (tx, ty, M11−1, M22−1, M21, M12) (tx, ty in px from the principal point)
// turned into the camera motion with its Unscented-Transform covariance (pose_uncertainty.h),
// through the contour paper's weak perspective (affine_pose.h) or the perspective model
// (perspective_pose.h; it needs the true principal point). The first frame is the template
// view: the plane fronto-parallel at Z0 on the optical axis. A frame's status is tracked, lost
// (too few edges: the prediction is kept) or singular (det M ≤ 0: no pose). Translation in the
// unit of Z0, angles in radians (RotationForm order).
//
// RenderSequence: the target (control points in its plane, Z0's unit) under the motion
// interpolated linearly from `from` to `to` (Tx, Ty, Tz in Z0's unit, Rx, Ry, Rz in degrees;
// R = Rz Ry Rx, x_camera = R p + (Tx, Ty, Z0 + Tz)), seen by a true pinhole with the principal
// point at the image centre ((W − 1)/2, (H − 1)/2): bright (180) on dark (60), rendered by
// render.h (area coverage, optics blur, pixel noise seeded with SplitMix64(seed) + frame,
// 8-bit). Each frame goes to a callback as it is rendered (a sequence may hold 2·10^9 pixels),
// with its motion and the weak-perspective S of it (ShapeFromPose).
//
// Options validate themselves (core/options_check.h): IsValid names the field and the range;
// SequenceTrackingOptions: the camera (ContourCamera.focal, .z0 finite and positive), the search
// range EdgeSearchOptions.range 2 … 200 px, a given ShapeTrackerOptions.measurement_sigma above
// 0 … 100 px, then the rest of ShapeTrackerOptions::IsValid; SequenceRenderOptions: the camera,
// frames 1 … 10000, width and height 8 … 20000 px (8: io/image_files.h's smallest readable side),
// at most 10^8 pixels a frame (io/image_files.h's largest readable image) and 2·10^9 over the
// sequence, RenderOptions.noise_sigma 0 … 255 grey levels, RenderOptions.blur_sigma 0 … 20 px, at
// least 4 target control points, then the rest of RenderOptions::IsValid (render.h). The ranges
// keep any one sequence within a workstation's memory and time.
//
// Errors: hecal::InputError for options that are not IsValid or an empty image;
// hecal::DegenerateError for a collinear contour (shape_space.h), from the constructor and from
// RenderSequence; an exception thrown by the frame callback passes through.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/contour/affine_pose.h"
#include "hecal/contour/gray_image.h"
#include "hecal/contour/perspective_pose.h"
#include "hecal/contour/pose_uncertainty.h"
#include "hecal/contour/render.h"
#include "hecal/contour/shape_tracker.h"
#include "hecal/core/limits.h"
#include "hecal/geometry/types.h"

namespace hecal::contour {

struct SequenceTrackingOptions {
  Eigen::Matrix2Xd control;                             // initial control points, first image (px)
  Eigen::Vector2d principal = Eigen::Vector2d::Zero();  // principal point (px)
  ContourCamera camera;                                 // focal (px), Z0
  RotationForm form = RotationForm::kZyx;
  bool perspective = false;  // the perspective pose model instead of weak perspective
  ShapeTrackerOptions tracker;

  static constexpr double kMinSearchRange = 2.0;         // px
  static constexpr double kMaxSearchRange = 200.0;       // px
  static constexpr double kMaxMeasurementSigma = 100.0;  // px
  bool IsValid(std::string* why) const;
};

enum class FrameStatus { kTracked, kLost, kSingular };
std::string_view FrameStatusName(FrameStatus status);  // "tracked", "lost", "singular"

struct SequenceFrame {
  TrackedFrame tracked;
  FrameStatus status = FrameStatus::kTracked;
  std::optional<ContourPoseUncertainty> pose;  // none when singular
};

// A frame of a sequence of image files: the file name and what was tracked in it.
struct TrackedImage {
  std::string image;
  SequenceFrame frame;
};

class SequenceTracker {
 public:
  explicit SequenceTracker(const SequenceTrackingOptions& options);
  // The next frame: tracked, and its pose with the UT covariance.
  SequenceFrame Track(const GrayImage& image);
  const ShapeTracker& tracker() const { return tracker_; }

 private:
  SequenceTrackingOptions options_;
  ShapeTracker tracker_;
  std::optional<PerspectivePoseModel> perspective_;
};

struct SequenceRenderOptions {
  Eigen::Matrix2Xd target;  // control points in the target plane (Z0's unit)
  ContourCamera camera;     // focal (px), Z0
  int frames = 30;
  Vector6d from = Vector6d::Zero();  // Tx, Ty, Tz (Z0's unit), Rx, Ry, Rz (deg)
  Vector6d to = Vector6d::Zero();
  int width = 0;  // px
  int height = 0;
  RenderOptions render;  // noise, blur, quantisation; the seed is set per frame
  std::uint64_t seed = 1;

  static constexpr int kMaxFrames = 10000;
  static constexpr int kMinSide = kMinImageSide;  // px (core/limits.h)
  static constexpr int kMaxSide = 20000;
  static constexpr std::int64_t kMaxFramePixels = kMaxImagePixels;
  static constexpr std::int64_t kMaxSequencePixels = 2000000000;
  static constexpr double kMaxNoise = 255.0;  // grey levels
  static constexpr double kMaxBlur = 20.0;    // px
  bool IsValid(std::string* why) const;
};

struct RenderedFrame {
  int index = 0;
  Vector6d motion = Vector6d::Zero();  // Tx, Ty, Tz, Rx, Ry, Rz (deg)
  Vector6d shape = Vector6d::Zero();   // the weak-perspective S of the motion
  bool outside = false;                // the target leaves the image
};

struct RenderedSequence {
  Eigen::Vector2d principal = Eigen::Vector2d::Zero();  // px
  Eigen::Matrix2Xd first_view;  // the control points in the first frame (px)
  std::vector<RenderedFrame> frames;
  int outside = 0;  // frames where the target leaves the image
};

// Renders every frame, handing each image to `on_frame` before the next is rendered.
RenderedSequence RenderSequence(
    const SequenceRenderOptions& options,
    const std::function<void(const RenderedFrame&, const GrayImage&)>& on_frame);

}  // namespace hecal::contour
