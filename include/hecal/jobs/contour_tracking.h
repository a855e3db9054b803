// Camera motion from a planar contour tracked through a folder of images as one job (`hecal
// contour track`; docs/contour.md, docs/cli.md#hecal-contour-track), printing nothing: the pose
// model line goes to JobCallbacks' progress (job_callbacks.h), every frame to `on_frame` as it
// is tracked.
//
// Steps (TrackContourImages)
//   1. The options checked (IsValid) before any file is read.
//   2. The initial contour read (io/contour_file.h: x,y in pixels of the first image). Points on
//      the curve (init_on_curve) become the control points of the closed cubic B-spline through
//      them (contour/bspline.h: ClosedBSpline::Interpolating); otherwise they are the control
//      points.
//   3. The principal point: the given one, else the centroid of the control points.
//   4. The pose model: perspective (contour/perspective_pose.h, the weak-perspective bias
//      removed; it needs the true principal point) or the contour paper's weak perspective
//      (contour/affine_pose.h); when not chosen, perspective exactly when the principal point is
//      given. Progress: "pose model: ..." naming it (one line).
//   5. contour::SequenceTracker (contour/sequence.h: shape-space Kalman filter, UT pose
//      covariance) over vision::TrackImageSequence (vision/contour_images.h: the folder's images
//      sorted by name, the first the template view).
// The result holds what report/contour_track_file.h writes (CSV or JSON): the tracker's set-up as
// used, the template shape, the edge polarity and every frame.
// Frames and units: image coordinates in pixels (origin at the centre of the top-left pixel);
// the motion of the camera relative to the template view, translation in the unit of Z0, angles
// in radians in the rotation form's order (contour/affine_pose.h).
//
// Errors (hecal::InputError): invalid options (source the field: ContourTrackingOptions.images,
// .init, ContourCamera.*, EdgeSearchOptions.range, ShapeTrackerOptions.*); those of the contour
// file, the images and the tracker (a collinear contour: hecal::DegenerateError) pass through.
// Nothing is written.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>

#include "hecal/contour/sequence.h"
#include "hecal/jobs/job_callbacks.h"
#include "hecal/report/contour_track_file.h"

namespace hecal::jobs {

struct ContourTrackingOptions {
  std::string images;                        // the folder of the image sequence
  std::string init;                          // the contour file of the first image (px)
  bool init_on_curve = false;                // its points lie on the curve (else: control points)
  std::optional<Eigen::Vector2d> principal;  // px; none: the centroid of the control points
  std::optional<bool> perspective;           // the pose model; none: perspective with `principal`
  // Camera, rotation form, tracker settings; control, principal and perspective are the job's
  // (from the fields above).
  contour::SequenceTrackingOptions tracking;

  // core/options_check.h: false naming the first bad field, in the order
  // ContourTrackingOptions.images, .init (empty), then SequenceTrackingOptions::IsValid.
  bool IsValid(std::string* why) const;
};

// Steps 1–5 above; `on_frame` (may be empty) receives every frame as soon as it is tracked.
report::ContourTrack TrackContourImages(
    const ContourTrackingOptions& options, const JobCallbacks& callbacks,
    const std::function<void(const contour::TrackedImage&)>& on_frame = {});

}  // namespace hecal::jobs
