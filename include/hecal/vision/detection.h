// Target detection in one image (docs/targets.md).
//
// DetectTarget finds the points of a pose::TargetSpec in an 8-bit image and labels each pixel
// with its pose::ObjectPoints id, so that solvePnP(ObjectPoints[id].position, pixel) gives
// T_camera_target in the target frame of hecal/pose/target.h (OpenCV 4.6's frame: x along the
// columns, y along the rows, z into the board). Pixels follow OpenCV: origin at the centre of the
// top-left pixel, u to the right, v down. The image may be grey or BGR(A); it is converted to grey.
//
// Per target type (OpenCV 4.6 + contrib aruco, libapriltag 3.3):
//   chessboard     cv::findChessboardCorners(ADAPTIVE_THRESH | NORMALIZE_IMAGE) with the corners
//                  refined from the edges between the squares (detection_edges.cc: intersections
//                  of the fitted grid lines; on real images as accurate as the SB detector's
//                  ACCURACY mode and twice as accurate as cv::cornerSubPix, at a 50th of its
//                  time); when it finds nothing, cv::findChessboardCornersSB(EXHAUSTIVE |
//                  ACCURACY), which copes with blur and uneven light. All or nothing.
//   circles,       cv::findCirclesGrid(SYMMETRIC_GRID | ASYMMETRIC_GRID), retried with CLUSTERING
//   acircles       when it fails (the default finder misses grids turned by about a quarter turn),
//                  with a blob detector that accepts blobs up to (image area / number of circles);
//                  each centre is then
//                  refined to the grey-level centroid of its dark blob (weights max(0, w − I) with
//                  w the 90th percentile of the window, inside a disc of half the smallest centre
//                  spacing, iterated to a fixed point). Under perspective this is the centroid of
//                  the imaged ellipse, which differs from the projected circle centre by
//                  O(f·r²·tilt/Z²) px (r the circle radius, Z the distance). All or nothing.
//   charuco        aruco::detectMarkers + aruco::refineDetectedMarkers, then
//                  aruco::interpolateCornersCharuco (local homographies) on
//                  CharucoBoard::create(cols, rows, square, marker, dictionary); its corners are
//                  refined again from the square edges (OpenCV 4.6 returns them 0.5 px off, see
//                  detection_markers.cc). Partial allowed.
//   aruco_grid     aruco::detectMarkers + refineDetectedMarkers on
//                  GridBoard::create(cols, rows, marker, spacing, dictionary, first_id); markers
//                  with ids outside first_id .. first_id + cols·rows − 1 are ignored. Marker
//                  m = id − first_id contributes its 4 corners as ids 4m + 0..3 (OpenCV's corner
//                  order: top-left, top-right, bottom-right, bottom-left). Corners are refined as
//                  intersections of the marker's fitted edges (detection_edges.cc; cv::cornerSubPix
//                  — CORNER_REFINE_SUBPIX — pulls these L-corners 0.15–0.25 px into the marker),
//                  in undistorted coordinates when the camera is given (below). Partial allowed.
//   apriltag_grid  libapriltag (apriltag_detector_detect, quad_decimate =
//                  options.apriltag_decimate, at most options.apriltag_max_hamming corrected
//                  bits), same id scheme as aruco_grid. libapriltag lists a tag's corners p[0..3]
//                  counter-clockwise as seen in the image (u right, v down), starting at the
//                  printed tag's bottom-left: bottom-left, bottom-right, top-right, top-left
//                  (apriltag_to_image row 0 at the top); id 4m + k takes p[3 − k], so the order
//                  and handedness are aruco's (clockwise in the image from the top-left).
//                  libapriltag puts pixel centres at +0.5, so 0.5 px is subtracted; corners are
//                  then refined like aruco_grid's. Render → detect tests check both against the
//                  projected corners.
//   aruco,         one tag: the detectors above on a 1 × 1 grid whose only marker is `id`, so its
//   apriltag       corners are point ids 0..3 (top-left, top-right, bottom-right, bottom-left).
//                  Every other tag in view is ignored. found or not_found (a tag is decoded
//                  whole or not at all).
//   Marker ids seen more than once are dropped (named in the message); ids of the dictionary /
//   family that are not the target's are ignored and named too (a wrong id or first_id shows).
//
// Status:
//   found      every point of the target (grid types), or every point of a marker target.
//   partial    marker targets only: at least options.min_points (≥ 4) points whose object points
//              are not all on one line; the message warns below 6 points (a weak pose).
//   not_found  nothing usable; the message says why.
//   ambiguous  a 180°-symmetric pattern (symmetric circle grid; chessboard with cols + rows even):
//              the points are complete but their order is fixed only up to a half turn, by
//              order_consistency.h's image rule. ResolveOrder (order_consistency.h) makes a set of
//              images consistent; never use an ambiguous detection on its own for a pose that must
//              agree with other images.
//
// Sharpness (Detection::sharpness) is an edge width in pixels (smaller = sharper; a Gaussian blur
// of σ px gives about 2.5σ): for chessboards cv::estimateChessboardSharpness (the width of the
// black-to-white transition between neighbouring square centres); for the other types the mean
// over the detected points of contrast / peak gradient in a window of half-size 0.45 × the
// distance to the nearest other detected point (contrast = 95th − 5th percentile of the grey
// levels, peak gradient = the h-th largest Sobel gradient magnitude, h the half-size, so that a
// few noisy pixels do not count). For a blurred step edge contrast / peak slope = √(2π)·σ ≈ 2.5σ,
// the same scale as OpenCV's measure; for a perfectly sharp edge the 3×3 Sobel operator limits it
// to about 2 px.
//
// The camera (optional): the image's intrinsics (pose/camera_model.h). Lens distortion bends a
// marker's straight sides, and corners intersected from lines fitted to the bent sides sit
// outward (0.1–0.3 px on 150–200 px tags with k1 = −0.12, a scale of the pose: docs/targets.md).
// With the camera the marker corners (aruco_grid, apriltag_grid, aruco, apriltag) are fitted and
// intersected in undistorted coordinates and distorted back to pixels (detection_edges.cc). The
// other types do not use it: the saddle corners of chessboards and ChArUco boards are fitted
// with curves that absorb the bending (measured: no outward offset beyond 0.002 px under strong
// barrel distortion, docs/targets.md), and circle centres are centroids. Without the camera
// marker corners carry that bias.
//
// Errors: hecal::InputError (source "target") when pose::CheckTarget rejects the spec, when the
// spec is a square chessboard or symmetric circle grid (cols == rows: a quarter turn maps it onto
// itself, so even handedness cannot fix the order); the InputError of DetectOptions::IsValid;
// InputError (source "image") for an empty image or one that is not 8-bit with 1, 3 or 4 channels;
// InputError (source "camera") for a camera whose fx, fy are not positive, whose values are not
// finite, or whose width × height (when set) is not the image's.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hecal/pose/camera_model.h"
#include "hecal/pose/target.h"

namespace hecal::vision {

enum class DetectionStatus { kFound, kPartial, kNotFound, kAmbiguous };

// "found" | "partial" | "not_found" | "ambiguous".
std::string_view DetectionStatusName(DetectionStatus status);

// How the ids of a detection's points were fixed (see order_consistency.h for the rules).
enum class PointOrder {
  kNone,         // not_found: no points
  kMarkers,      // decoded marker ids (charuco, aruco_grid, apriltag_grid)
  kPattern,      // the pattern's own asymmetry: handedness, square colours or the grid's shape
  kImage,        // 180°-symmetric pattern, half turn chosen by the image rule (status ambiguous)
  kReference,    // the image rule of this image fixed the order of a set (ResolveOrder)
  kConsistency,  // made consistent with the set's reference image by ResolveOrder
};

// "none" | "markers" | "pattern" | "image" | "reference" | "consistency".
std::string_view PointOrderName(PointOrder order);

struct ImagePoint {
  int id = 0;                                       // pose::ObjectPoints id
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();  // sub-pixel position, pixels
};

struct Detection {
  DetectionStatus status = DetectionStatus::kNotFound;
  std::vector<ImagePoint> points;  // sorted by id, each id at most once
  int total_points = 0;            // points the target has (pose::PointCount)
  double sharpness = std::numeric_limits<double>::quiet_NaN();  // mean edge width, px
  PointOrder order = PointOrder::kNone;
  std::string message;  // one line: what was found, or why not

  int num_points() const { return static_cast<int>(points.size()); }
  // True for found and partial: the points may be used for a pose.
  bool usable() const {
    return status == DetectionStatus::kFound || status == DetectionStatus::kPartial;
  }
};

struct DetectOptions {
  int min_points = 4;                 // partial detections need at least this many points (≥ 4)
  bool allow_partial = true;          // false: marker targets must show every point
  bool chessboard_fast_first = true;  // findChessboardCorners + edge refinement, SB on failure;
                                      // false: findChessboardCornersSB only
  int apriltag_max_hamming = 1;       // corrected bits accepted by libapriltag (0..2)
  double apriltag_decimate = 1.0;     // libapriltag quad_decimate (1 = full resolution)

  // core/options_check.h: false naming DetectOptions.min_points (below 4),
  // .apriltag_max_hamming (not 0 … 2) or .apriltag_decimate (below 1 or not finite).
  bool IsValid(std::string* why) const;
};

Detection DetectTarget(const cv::Mat& image, const pose::TargetSpec& target,
                       const DetectOptions& options = {},
                       const std::optional<pose::CameraModel>& camera = std::nullopt);

}  // namespace hecal::vision
