// Generic image features matched between two images of a station pair, for the target-free
// hand–eye search (`hecal calibrate --method global --images DIR --target none`; docs/global.md).
//
// Algorithm
//   1. DetectFeatures: SIFT keypoints and descriptors (OpenCV 4.6 features2d, cv::SIFT; Lowe,
//      "Distinctive image features from scale-invariant keypoints", IJCV 2004) or ORB ones
//      (cv::ORB; Rublee et al., "ORB: an efficient alternative to SIFT or SURF", ICCV 2011;
//      binary descriptors) on the 8-bit grey image, at most `max_features` of the strongest
//      (SIFT: 0 = all). OpenCV 4.6's SIFT first upsamples the image 2× by linear interpolation,
//      where pixel x lies at x/2 − 0.25 of the image, and reports a point found at x as x/2: every
//      keypoint 0.25 px right of and below the point it describes, in effect a principal point
//      0.25 px off, which biased X on rendered scenes by about 2 σ per axis (docs/global.md,
//      "Measured"). DetectFeatures subtracts 0.25 px from both coordinates of SIFT keypoints
//      (checked by mirroring an image: feature_matches_test). ORB's keypoints are left as
//      OpenCV gives them.
//   2. MatchFeatures: for every descriptor of the first image its two nearest neighbours in the
//      second (brute force; L2 for SIFT, Hamming for ORB's binary descriptors); kept when the
//      nearest is closer than `ratio` (0.8, Lowe's ratio test) times the second nearest, in both
//      directions, and when the two directions pick each other (mutual check).
//   3. Every kept pixel is undistorted with the camera's plumb_bob model (pose/camera_model.h) to
//      normalised image coordinates (a match with a pixel that cannot be undistorted is dropped);
//      an essential matrix is fitted by RANSAC on them (cv::findEssentialMat, five-point solver,
//      identity camera matrix) with the threshold 4√2 · pixel_sigma / focal (normalised units; the
//      same threshold as the search's own epipolar pre-filter, global/outlier_removal.h), and only
//      its inliers are kept.
//   4. At most `max_matches` are returned, spread over the first image: it is cut into a
//      ⌈√max_matches⌉² grid of cells, and the matches are taken round by round, the best
//      (smallest descriptor distance) remaining match of every cell per round.
//
// MatchConsecutiveImages runs the steps over a sequence of station images: every image is read
// as grey (vision/image_read.h) and its features detected, in parallel over images on `threads`
// (0 = every core; cv::parallel_for_), then image k is matched with image k + 1. Errors are
// raised for the first image (or pair) in sequence order, whatever the scheduling.
//
// Frames and units: pixels with the origin at the centre of the top-left pixel (OpenCV); rays are
// unit vectors in the camera frame (z forward, x right, y down), in the first and the second
// image's camera respectively — global::BearingPair's v and u.
//
// Refused (hecal::InputError, exit 2 in the CLI): an unreadable image, or one whose size is not
// the camera's width × height (when the camera has them), naming the image; fewer than
// `min_matches` matches left after step 3 (a pair with too little texture or overlap, or a mostly
// rotating camera whose essential matrix is undetermined); images that are not 8-bit grey (a
// programming error: std::invalid_argument).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "hecal/pose/camera_model.h"

namespace hecal::vision {

struct ImageFeatures {
  cv::Size size;  // of the image
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;  // one row per keypoint (SIFT: CV_32F, 128 columns; ORB: CV_8U, 32)
};

enum class FeatureKind { kSift, kOrb };

struct FeatureMatchOptions {
  double ratio = 0.8;        // Lowe's ratio test
  double pixel_sigma = 0.5;  // keypoint noise per axis, pixels (sets the RANSAC threshold)
  int max_matches = 40;      // returned per pair, spread over the image; ≥ min_matches
  int min_matches = 8;       // fewer RANSAC inliers are refused; ≥ 5 (the essential matrix)
  FeatureKind kind = FeatureKind::kSift;

  // core/options_check.h: false naming FeatureMatchOptions.ratio (not in (0, 1]),
  // .pixel_sigma (not positive and finite), .min_matches (below 5) or .max_matches (below
  // min_matches).
  bool IsValid(std::string* why) const;
};

struct FeatureMatch {
  Eigen::Vector2d first_pixel;
  Eigen::Vector2d second_pixel;
  Eigen::Vector3d first_ray;   // unit, first camera frame
  Eigen::Vector3d second_ray;  // unit, second camera frame
  float distance = 0.0f;       // descriptor distance
};

// Step 1.
ImageFeatures DetectFeatures(const cv::Mat& gray, int max_features = 8000,
                             FeatureKind kind = FeatureKind::kSift);

// Steps 2–4. `first_name` and `second_name` name the images in errors.
std::vector<FeatureMatch> MatchFeatures(const ImageFeatures& first, const ImageFeatures& second,
                                        const pose::CameraModel& camera,
                                        const FeatureMatchOptions& options,
                                        const std::string& first_name,
                                        const std::string& second_name);

// Steps 1–4 over consecutive images: element k holds the matches of image k with image k + 1.
// `names` name the images in errors (one per path).
std::vector<std::vector<FeatureMatch>> MatchConsecutiveImages(
    const std::vector<std::filesystem::path>& paths, const std::vector<std::string>& names,
    const pose::CameraModel& camera, const FeatureMatchOptions& options, int threads);

}  // namespace hecal::vision
