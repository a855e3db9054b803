// `hecal detect --images DIR --target target.yaml [--intrinsics camera.yaml] --output camera.csv
//               [--threads N]`                                              (DESIGN.md §4, §4.1)
// Camera poses T_camera_target from images of a calibration target, for `hecal calibrate`.
//
// Steps
//   1. Images: every *.png, *.jpg, *.jpeg, *.bmp, *.tif, *.tiff in DIR (extension case-
//      insensitive, not recursive), sorted by file name; all must have the same size.
//   2. Detection: vision::DetectTarget on each image (grey), in parallel over images on N
//      threads (--threads, default 0 = every core; cv::parallel_for_). Chessboards and
//      symmetric circle grids whose order is fixed only up to a half turn are made consistent
//      across the images by vision::ResolveOrder (image rule); those still ambiguous are skipped.
//   3. Intrinsics: --intrinsics camera.yaml (io/camera_file.h), or, without it, estimated from
//      the usable images by vision::CalibrateIntrinsics (cv::calibrateCamera, plumb_bob with k3),
//      printed with their 1σ and RMS, and written to <output stem>.camera.yaml. Its warnings
//      (few views, poor coverage, large σ) go to stderr; nearly parallel boards (normals within
//      IntrinsicsOptions::min_normal_spread_deg = 10° of each other) are refused, since focal
//      length and distance are then confounded while calibrateCamera's σ look fine.
//   4. Poses: OpenCV IPPE (planar targets; SQPnP otherwise) refined by SOLVEPNP_ITERATIVE
//      (vision::SolvePnPOpenCvRefined), then hecal's Levenberg–Marquardt refinement with its
//      covariance (pose::RefinePose, σ estimated from each image's residuals).
//   5. Report (stdout): one row per image — file, status (found | partial | not_found |
//      ambiguous), points found / points of the target, sharpness (edge width, px; smaller is
//      sharper), reprojection RMS at the refined pose (px; with estimated intrinsics this is
//      calibrateCamera's per-view RMS), the pose's 1σ per axis (translation mm, rotation deg:
//      sqrt(trace/3) of each 3×3 block of the covariance) — and for skipped images the reason.
//   6. Files (metres, written only when everything succeeded, each atomically):
//      <output>                  pose table (io/pose_table.h): id (= image file stem),
//                                x,y,z,qw,qx,qy,qz of T_camera_target, '#' lines saying how
//      <output stem>.points.csv  id,point_id,u,v: the detected pixels of every used image
//                                (point_id = the pose::ObjectPoints id)
//      <output stem>.camera.yaml only when the intrinsics were estimated
//   The output stem is <output> without its extension (camera.csv → camera).
//
// Errors (hecal::InputError, exit 2, nothing written): a missing directory or one without images;
// an unreadable image (names it); images of different sizes; intrinsics for another image size;
// a target found in no image (for a chessboard: "cols/rows are INNER corners"); a target found in
// fewer than 3 images (hand–eye calibration and intrinsics estimation both need 3); intrinsics
// that cannot be estimated from the images (then --intrinsics is needed); bad --threads. The
// target and camera files are read before any image, so their errors come at once.
#pragma once

#include <string>

#include "cli.h"

namespace hecal::cli {

struct DetectFlags {
  std::string images;
  std::string target;
  std::string intrinsics;  // "" = estimate from the images
  std::string output;
  int threads = 0;  // 0 = every core
};

// Runs the command; throws hecal::InputError for bad flags or data.
void RunDetect(const DetectFlags& flags, const Io& io);

}  // namespace hecal::cli
