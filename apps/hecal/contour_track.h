// `hecal contour track` and `hecal contour render` (docs/contour.md): follow a
// planar contour through an image sequence with the shape-space Kalman filter
// (contour/shape_tracker.h) and turn every shape vector into the camera motion with its UT
// covariance (contour/pose_uncertainty.h); and render synthetic sequences with known motion to
// try it on (contour/render.h). The jobs are contour::SequenceTracker and
// contour::RenderSequence (contour/sequence.h) with the images read and encoded by
// vision/contour_images.h; these commands parse the flags, print and write the files.
//
// hecal contour track --images DIR --init contour.csv --focal F_PX --z0 Z0
//                     [--principal-point CX,CY] [--init-points control|curve]
//                     [--subspace full|similarity|translation-scale|planar-robot|translation]
//                     [--rotation zyx|zxz] [--measurement-sigma PX] [--search-range PX]
//                     [--output track.csv|track.json]
//   Images: every *.png, *.jpg, *.jpeg, *.bmp, *.tif, *.tiff in DIR (not recursive), sorted by
//   file name, read as 8-bit grey (OpenCV: needs the vision layer), all of one size. The first
//   is the template view: the plane fronto-parallel at Z0 on the optical axis (affine_pose.h).
//   contour.csv: header `x,y`, pixel coordinates in the first image (origin at the centre of
//   the top-left pixel), the control points of a closed cubic B-spline (--init-points control,
//   default) or points on the curve (curve: the B-spline through them). The principal point
//   defaults to the centroid of the control points (the target origin in the first view).
//   --measurement-sigma: the edge-location σ in px (default: estimated from the residuals of
//   every frame); --search-range: ±px searched along each normal (default 10).
//   Output (stdout): one line per frame. --output writes, atomically, CSV (one row per frame:
//   frame, image, status, edges, σ, residual RMS, S, sd(S), the pose and its sd, the bias flag)
//   or JSON (full 6 × 6 covariances), chosen by the extension. Units: tx, ty and their sd in px;
//   M entries dimensionless; translation in the unit of --z0; angles in degrees in the CSV and
//   in the JSON's *_deg fields, radians in the JSON's covariance (stated in "units"); both
//   written by report/contour_track_file.h.
//   status: tracked | lost (too few edges: the prediction is kept) | singular (det M ≤ 0: no
//   pose). bias: the bias check (UT mean vs the pose of the mean shape) flagged a
//   parameter — expected while the tilt is small (Necker fold).
//
// hecal contour render --output DIR --frames N --from TX,TY,TZ,RX,RY,RZ --to TX,TY,TZ,RX,RY,RZ
//                      --focal F_PX --z0 Z0 --size W,H [--contour target.csv] [--noise GREY]
//                      [--blur PX] [--seed S]
//   The target (control points x,y in its plane, Z0's unit; default: the built-in 12-point
//   irregular contour of contour_study.h, ≈ 250 × 180 mm) under the motion interpolated
//   linearly from --from to --to (mm and degrees; R = Rz Ry Rx, x_camera = R p + (Tx, Ty,
//   Z0 + Tz)), seen by a true pinhole with the principal point at the image centre
//   ((W − 1)/2, (H − 1)/2): bright (180) on dark (60), area-coverage anti-aliasing, Gaussian
//   optics blur (--blur, default 0.7 px), pixel noise (--noise, default 3 grey levels; --seed,
//   default 1), 8-bit. Writes DIR/frame_0000.png …, DIR/truth.csv (per frame: the motion, and
//   the weak-perspective S = ShapeFromPose of it) and DIR/init.csv (x,y: the control points of
//   the first view in pixels, ready for `track --init`), and records --seed in truth.csv. DIR
//   is created when missing. Every file is staged in DIR and renamed when all are rendered: a
//   failure (a frame with the target behind the camera, a file that cannot be written) leaves
//   none of them, and removes DIR when it was created. Bounds (bounds.h): 1 … 10000 frames,
//   8 … 20000 px a side, ≤ 10^8 pixels a frame and 2·10^9 in all, --noise 0 … 255.
// Errors: bad flags or files (with file:line), a missing or empty folder, an unreadable image
// (vision/image_read.h: larger than 10^8 pixels, smaller than 8 × 8, cut short or corrupt), an
// --output that is --init or not a regular file (io/atomic_file.h), images of different sizes, a
// collinear init contour (DegenerateError) → exit 2; no output file is written then (track writes
// its output only when every frame is done).
#pragma once

#include <string>

#include "cli.h"

namespace hecal::cli {

// Flags as given (numbers are parsed by the Run functions, so errors name the flag).
struct ContourTrackOptions {
  std::string images;
  std::string init;
  std::string focal;
  std::string z0;
  std::string principal_point;  // "" = centroid of the control points
  std::string init_points = "control";
  std::string subspace = "full";
  std::string rotation = "zyx";
  std::string measurement_sigma;  // "" = estimate
  std::string search_range = "10";
  std::string pose_model = "auto";  // auto | weak | perspective
  std::string output;
};
void RunContourTrack(const ContourTrackOptions& options, const Io& io);

struct ContourRenderOptions {
  std::string output;
  std::string contour;  // "" = built-in target
  std::string frames = "30";
  std::string from = "0,0,0,0,0,0";
  std::string to;
  std::string focal;
  std::string z0;
  std::string size;
  std::string noise = "3";
  std::string blur = "0.7";
  std::string seed = "1";
};
void RunContourRender(const ContourRenderOptions& options, const Io& io);

}  // namespace hecal::cli
