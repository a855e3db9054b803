// The image front end shared by `hecal detect` and `hecal calibrate --images` (docs/cli.md,
// §4.1): from a folder of target images to camera poses T_camera_target with covariances.
//
// Steps (DetectImageSet)
//   1. Images: the stations of the folder (image_files.h): every *.png, *.jpg, *.jpeg, *.bmp,
//      *.tif, *.tiff in it (station id = file stem), or when it holds none, one image in each
//      sub-folder (station id = sub-folder name); sorted by name. All must have the same size.
//   2. Detection: vision::DetectTarget on each image (grey), in parallel over images on N
//      threads (0 = every core; cv::parallel_for_), with the given intrinsics: the corners of
//      markers and single tags are then fitted in undistorted coordinates, free of the outward
//      bias that lens distortion gives corners fitted on its bent edges (detection.h, "The
//      camera"; docs/targets.md). Intrinsics estimated in step 3 do not exist yet, and those
//      images are not detected again: the estimate itself rests on the biased corners, so
//      removing the bias would mean iterating detection and calibration over every image, while
//      the targets that estimate intrinsics well are the boards whose saddle corners carry no
//      such bias (chessboard, ChArUco); single tags require the intrinsics anyway. Chessboards
//      and symmetric circle grids whose order is fixed only up to a half turn are made
//      consistent across the images by vision::ResolveOrder (image rule); those still ambiguous
//      are skipped.
//   3. Intrinsics: the given camera.yaml (io/camera_file.h), whose width × height, when it has
//      them, must be the images' size; or, without it, estimated from the usable images by
//      vision::CalibrateIntrinsics (cv::calibrateCamera, plumb_bob with k3), printed with their
//      1σ and RMS. Its warnings (few views, poor coverage, large σ) go to stderr; nearly parallel
//      boards (normals within IntrinsicsOptions::min_normal_spread_deg = 10° of each other) are
//      refused, since focal length and distance are then confounded while calibrateCamera's σ
//      look fine; so are single tags (4 points per image cannot determine K and distortion).
//   4. Poses: OpenCV IPPE (planar targets; SQPnP otherwise) refined by SOLVEPNP_ITERATIVE
//      (vision::SolvePnPOpenCvRefined), then hecal's Levenberg–Marquardt refinement with its
//      covariance (pose::RefinePose, σ estimated from each image's residuals).
//   5. Report (stdout): one row per image — file, status (found | partial | not_found |
//      ambiguous), points found / points of the target, sharpness (edge width, px; smaller is
//      sharper), reprojection RMS at the refined pose (px), the pose's 1σ per axis (translation
//      mm, rotation deg: sqrt(trace/3) of each 3×3 block of the covariance) — and for skipped
//      images the reason.
//   6. Given intrinsics checked against the images (vision/intrinsics_fit.h): a median
//      reprojection RMS of 2 px or more is an error, a fit clearly worse than a free homography's
//      a warning on stderr; both name the likely mistake (cx/cy swapped, fx/fy scaled, the
//      intrinsics of another resolution, images already undistorted) when one of those
//      corrections makes the images fit, else what to check.
//
// Usable images needed (ImageUse): hand–eye calibration 3 stations (2 motions); poses with given
// intrinsics 1 (`hecal detect --intrinsics`); estimating the intrinsics 3 views (Zhang). The
// message says which rule applies.
//
// Errors (hecal::InputError, exit 2): a missing folder or one without images; a station
// sub-folder without an image or with several (names it); an unreadable image (names it); images
// of different sizes; intrinsics for another image size (both sizes named; when the images are
// the camera's size scaled by one factor, the message says so and gives the scaled fx, fy, cx,
// cy); given intrinsics that do not fit the images (step 6); a target found in no image (for a
// chessboard: "cols/rows are INNER corners"); fewer usable
// images than the use needs; intrinsics that cannot be estimated from the images (then
// --intrinsics is needed); a single-tag target without --intrinsics; a negative thread count.
// The target and camera files are read before any image, so their errors come at once.
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

// What the images are for (the least number of usable images, above).
enum class ImageUse { kHandEye, kPoses };

struct ImageSetFlags {
  std::string images;      // --images DIR
  std::string target;      // --target target.yaml
  std::string intrinsics;  // --intrinsics camera.yaml; "" = estimate from the images
  int threads = 0;         // --threads; 0 = every core
  ImageUse use = ImageUse::kHandEye;
};

// One image: where it is, what was found, and what became of it.
struct ImageRecord {
  std::filesystem::path path;
  std::string station;  // the station id: the file stem, or the sub-folder's name
  std::string name;     // for reports: "im_00.png", or "pose_00/image.png"
  cv::Size size;
  vision::Detection detection;
  std::string skipped;  // why the image is not used; empty when used
  std::optional<pose::RefinementResult> pose;

  bool used() const { return skipped.empty(); }
  std::string id() const { return station; }
};

struct ImageSet {
  pose::TargetSpec target;
  std::vector<pose::ObjectPoint> board;               // pose::ObjectPoints(target)
  std::vector<ImageRecord> images;                    // every station of the folder, sorted by name
  cv::Size size;                                      // of every image
  pose::CameraModel camera;                           // given or estimated
  std::optional<vision::IntrinsicsResult> estimated;  // when estimated from the images
};

// Steps 1–5 above; `command` names the caller in the first line printed ("hecal detect").
ImageSet DetectImageSet(const ImageSetFlags& flags, const std::string& command, const Io& io);

// "chessboard 24x17", "apriltag tag36h11 id 5".
std::string Describe(const pose::TargetSpec& target);

// The target points of a detection (metres, target frame) and their pixels, in the same order.
std::vector<Eigen::Vector3d> ObjectPointsOf(const vision::Detection& detection,
                                            const std::vector<pose::ObjectPoint>& board);
std::vector<Eigen::Vector2d> PixelsOf(const vision::Detection& detection);

}  // namespace hecal::cli
