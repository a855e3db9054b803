// The image front end (`hecal detect`, `hecal calibrate --images`; docs/targets.md): from a
// folder of target images to camera poses T_camera_target (metres, target frame → camera frame)
// with covariances (right perturbation, rotation first; pose/pose_refinement.h). The job writes
// and prints nothing: it returns an ImageSet and reports its stages to an optional
// ImageSetProgress (jobs/image_front_end.h hands them out as text, for the CLI to print).
//
// Steps (DetectImageSet)
//   1. Images: the target file (io/target_file.h), the camera file when given, then the stations
//      of the folder (io/image_files.h): every *.png, *.jpg, *.jpeg, *.bmp,
//      *.tif, *.tiff in it (station id = file stem), or when it holds none, one image in each
//      sub-folder (station id = sub-folder name); sorted by name. All must have the same size.
//   2. Detection: vision::DetectTarget on each image (grey, vision/image_read.h), in parallel over
//   images on N
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
//      are skipped. Each image is checked against the description (vision/target_mismatch.h: a
//      chessboard inside a larger board or one corner off, a marker grid laid out the other way,
//      the wrong dictionary or family); the first image that contradicts it refuses the set at
//      once, naming the target file, and the images after it are not detected.
//   3. Intrinsics: the given camera.yaml (io/camera_file.h), whose width × height, when it has
//      them, must be the images' size; or, without it, estimated from the usable images by
//      vision::CalibrateIntrinsics (cv::calibrateCamera, plumb_bob with k3), with their 1σ, RMS
//      and warnings (few views, poor coverage, large σ) in ImageSet::estimated; nearly parallel
//      boards (normals within IntrinsicsOptions::min_normal_spread_deg = 10° of each other) are
//      refused, since focal length and distance are then confounded while calibrateCamera's σ
//      look fine; so are single tags (4 points per image cannot determine K and distortion).
//   4. Poses: OpenCV IPPE (planar targets; SQPnP otherwise) refined by SOLVEPNP_ITERATIVE
//      (vision::SolvePnPOpenCvRefined), then hecal's Levenberg–Marquardt refinement with its
//      covariance (pose::RefinePose, σ estimated from each image's residuals).
//   5. Every image keeps what became of it: its detection, its refined pose, or why it is
//      skipped (ImageRecord).
//   6. Given intrinsics checked against the images (vision/intrinsics_fit.h): a median
//      reprojection RMS of 2 px or more is an error, a fit clearly worse than a free homography's
//      a warning (ImageSet::fit_warning); both name the likely mistake (cx/cy swapped, fx/fy
//      scaled, the intrinsics of another resolution, images already undistorted) when one of those
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
// cy); given intrinsics that do not fit the images (step 6); a description an image contradicts
// (step 2, names the image, what it shows and the fix); a target found in no image (for a
// chessboard: "cols/rows are INNER corners"); fewer usable
// images than the use needs; intrinsics that cannot be estimated from the images (then
// --intrinsics is needed); a single-tag target without --intrinsics; options that are not valid
// (ImageSetOptions::IsValid). The target and camera files are read before any image, so their
// errors come at once. The messages name the CLI's --intrinsics where the remedy is to give or
// leave out the intrinsics.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <functional>
#include <opencv2/core/types.hpp>
#include <optional>
#include <string>
#include <vector>

#include "hecal/pose/pose_refinement.h"
#include "hecal/pose/target.h"
#include "hecal/vision/detection.h"
#include "hecal/vision/intrinsics_calibration.h"

namespace hecal::vision {

// What the images are for (the least number of usable images, above).
enum class ImageUse { kHandEye, kPoses };

struct ImageSetOptions {
  std::string images;      // the image folder
  std::string target;      // target.yaml (io/target_file.h)
  std::string intrinsics;  // camera.yaml or ViSP XML (io/camera_file.h); "" = estimate them
  int threads = 0;         // detection threads; 0 = every core, at most kMaxThreads
  ImageUse use = ImageUse::kHandEye;

  // core/options_check.h: false naming ImageSetOptions.images or .target (empty) or .threads
  // (outside 0 … kMaxThreads, core/limits.h).
  bool IsValid(std::string* why) const;
};

// One image: where it is, what was found, and what became of it.
struct ImageRecord {
  std::filesystem::path path;
  std::string station;  // the station id: the file stem, or the sub-folder's name
  std::string name;     // for reports: "im_00.png", or "pose_00/image.png"
  cv::Size size;
  Detection detection;
  std::string skipped;  // why the image is not used; empty when used
  std::optional<pose::RefinementResult> pose;

  bool used() const { return skipped.empty(); }
  std::string id() const { return station; }
};

struct ImageSet {
  pose::TargetSpec target;
  std::vector<pose::ObjectPoint> board;       // pose::ObjectPoints(target)
  std::vector<ImageRecord> images;            // every station of the folder, sorted by name
  bool sub_folders = false;                   // one sub-folder per station (io/image_files.h)
  std::string listing_note;                   // sub-folders hidden by top-level images, if any
  cv::Size size;                              // of every image
  pose::CameraModel camera;                   // given or estimated
  std::vector<std::string> camera_notes;      // the camera file's notes (io::CameraFile::notes)
  std::optional<IntrinsicsResult> estimated;  // when estimated from the images
  std::string fit_warning;  // step 6: "FILE: the intrinsics fit the images poorly: ..." or ""

  int CountUsed() const;
};

// Called as the job runs, for callers that report progress (each may be empty): after step 1
// (the target, the camera file and the folder read), after step 2 (before the number of usable
// images is checked), after step 3 and after step 4 (before the last checks).
struct ImageSetProgress {
  std::function<void(const ImageSet&)> listed;
  std::function<void(const ImageSet&)> detected;
  std::function<void(const ImageSet&)> intrinsics;
  std::function<void(const ImageSet&)> posed;
};

// The least number of usable images for `options` (above).
int ImagesNeeded(const ImageSetOptions& options);

// Steps 1–4 and 6 above.
ImageSet DetectImageSet(const ImageSetOptions& options, const ImageSetProgress& progress = {});

// "chessboard 24x17", "apriltag tag36h11 id 5".
std::string Describe(const pose::TargetSpec& target);

// The target points of a detection (metres, target frame) and their pixels, in the same order.
std::vector<Eigen::Vector3d> ObjectPointsOf(const Detection& detection,
                                            const std::vector<pose::ObjectPoint>& board);
std::vector<Eigen::Vector2d> PixelsOf(const Detection& detection);

}  // namespace hecal::vision
