// The image front end shared by `hecal detect` and `hecal calibrate --images` (DESIGN.md §4,
// §4.1): from a folder of target images to camera poses T_camera_target with covariances.
//
// Steps (DetectImageSet)
//   1. Images: every *.png, *.jpg, *.jpeg, *.bmp, *.tif, *.tiff in the folder (extension case-
//      insensitive, not recursive), sorted by file name; all must have the same size.
//   2. Detection: vision::DetectTarget on each image (grey), in parallel over images on N
//      threads (0 = every core; cv::parallel_for_). Chessboards and symmetric circle grids whose
//      order is fixed only up to a half turn are made consistent across the images by
//      vision::ResolveOrder (image rule); those still ambiguous are skipped.
//   3. Intrinsics: the given camera.yaml (io/camera_file.h), or, without it, estimated from the
//      usable images by vision::CalibrateIntrinsics (cv::calibrateCamera, plumb_bob with k3),
//      printed with their 1σ and RMS. Its warnings (few views, poor coverage, large σ) go to
//      stderr; nearly parallel boards (normals within IntrinsicsOptions::min_normal_spread_deg
//      = 10° of each other) are refused, since focal length and distance are then confounded
//      while calibrateCamera's σ look fine.
//   4. Poses: OpenCV IPPE (planar targets; SQPnP otherwise) refined by SOLVEPNP_ITERATIVE
//      (vision::SolvePnPOpenCvRefined), then hecal's Levenberg–Marquardt refinement with its
//      covariance (pose::RefinePose, σ estimated from each image's residuals).
//   5. Report (stdout): one row per image — file, status (found | partial | not_found |
//      ambiguous), points found / points of the target, sharpness (edge width, px; smaller is
//      sharper), reprojection RMS at the refined pose (px), the pose's 1σ per axis (translation
//      mm, rotation deg: sqrt(trace/3) of each 3×3 block of the covariance) — and for skipped
//      images the reason.
//
// Errors (hecal::InputError, exit 2): a missing folder or one without images; an unreadable
// image (names it); images of different sizes; intrinsics for another image size; a target found
// in no image (for a chessboard: "cols/rows are INNER corners"); a target found in fewer than 3
// images (hand–eye calibration and intrinsics estimation both need 3); intrinsics that cannot be
// estimated from the images (then --intrinsics is needed); a negative thread count. The target
// and camera files are read before any image, so their errors come at once.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <opencv2/core/types.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli.h"
#include "hecal/pose/pose_refinement.h"
#include "hecal/pose/target.h"
#include "hecal/vision/detection.h"
#include "hecal/vision/intrinsics_calibration.h"

namespace hecal::cli {

struct ImageSetFlags {
  std::string images;      // --images DIR
  std::string target;      // --target target.yaml
  std::string intrinsics;  // --intrinsics camera.yaml; "" = estimate from the images
  int threads = 0;         // --threads; 0 = every core
};

// One image: where it is, what was found, and what became of it.
struct ImageRecord {
  std::filesystem::path path;
  cv::Size size;
  vision::Detection detection;
  std::string skipped;  // why the image is not used; empty when used
  std::optional<pose::RefinementResult> pose;

  bool used() const { return skipped.empty(); }
  std::string id() const { return path.stem().string(); }  // the station id: the file stem
};

struct ImageSet {
  pose::TargetSpec target;
  std::vector<pose::ObjectPoint> board;  // pose::ObjectPoints(target)
  std::vector<ImageRecord> images;       // every image of the folder, sorted by file name
  cv::Size size;                         // of every image
  pose::CameraModel camera;              // given or estimated
  std::optional<vision::IntrinsicsResult> estimated;  // when estimated from the images
};

// Steps 1–5 above; `command` names the caller in the first line printed ("hecal detect").
ImageSet DetectImageSet(const ImageSetFlags& flags, const std::string& command, const Io& io);

// "chessboard 24x17".
std::string Describe(const pose::TargetSpec& target);

// The target points of a detection (metres, target frame) and their pixels, in the same order.
std::vector<Eigen::Vector3d> ObjectPointsOf(const vision::Detection& detection,
                                            const std::vector<pose::ObjectPoint>& board);
std::vector<Eigen::Vector2d> PixelsOf(const vision::Detection& detection);

}  // namespace hecal::cli
