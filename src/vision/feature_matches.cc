// Generic feature matching between two images (vision/feature_matches.h).
#include "hecal/vision/feature_matches.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <map>
#include <opencv2/calib3d.hpp>
#include <opencv2/features2d.hpp>
#include <optional>
#include <stdexcept>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/vision/image_read.h"

namespace hecal::vision {
namespace {

// Binary (ORB) descriptors are compared by Hamming distance, float (SIFT) ones by L2.
int DescriptorNorm(const cv::Mat& descriptors) {
  return descriptors.depth() == CV_8U ? cv::NORM_HAMMING : cv::NORM_L2;
}

// For each query descriptor, its nearest train descriptor when it passes the ratio test, else -1.
std::vector<int> RatioMatches(const cv::Mat& query, const cv::Mat& train, double ratio) {
  std::vector<int> best(query.rows, -1);
  if (query.empty() || train.rows < 2) return best;
  cv::BFMatcher matcher(DescriptorNorm(query));
  std::vector<std::vector<cv::DMatch>> knn;
  matcher.knnMatch(query, train, knn, 2);
  for (const std::vector<cv::DMatch>& k : knn) {
    if (k.size() == 2 && k[0].distance < ratio * k[1].distance) best[k[0].queryIdx] = k[0].trainIdx;
  }
  return best;
}

}  // namespace

ImageFeatures DetectFeatures(const cv::Mat& gray, int max_features, FeatureKind kind) {
  if (gray.empty() || gray.type() != CV_8UC1) {
    throw std::invalid_argument("DetectFeatures: the image must be 8-bit grey");
  }
  ImageFeatures features;
  features.size = gray.size();
  const cv::Ptr<cv::Feature2D> detector =
      kind == FeatureKind::kOrb
          ? cv::Ptr<cv::Feature2D>(cv::ORB::create(max_features > 0 ? max_features : 8000))
          : cv::Ptr<cv::Feature2D>(cv::SIFT::create(std::max(0, max_features)));
  detector->detectAndCompute(gray, cv::noArray(), features.keypoints, features.descriptors);
  if (kind == FeatureKind::kSift) {
    // OpenCV's SIFT reports x/2 for a point found at x in its 2× linear upsampling, which lies at
    // x/2 − 0.25 of the image (feature_matches.h, step 1).
    for (cv::KeyPoint& keypoint : features.keypoints) keypoint.pt -= cv::Point2f(0.25f, 0.25f);
  }
  return features;
}

bool FeatureMatchOptions::IsValid(std::string* why) const {
  if (!(ratio > 0.0 && ratio <= 1.0)) {
    return Invalid(why, "FeatureMatchOptions.ratio", "must be above 0 and at most 1",
                   "use e.g. 0.8 (Lowe's ratio test)");
  }
  if (!(pixel_sigma > 0.0) || !std::isfinite(pixel_sigma)) {
    return Invalid(why, "FeatureMatchOptions.pixel_sigma", "must be positive and finite",
                   "give the keypoint noise per axis in pixels, e.g. 0.5");
  }
  if (min_matches < 5) {
    return Invalid(
        why, "FeatureMatchOptions.min_matches",
        "must be at least 5 (an essential matrix needs them), got " + std::to_string(min_matches),
        "use e.g. 8");
  }
  if (max_matches < min_matches) {
    return Invalid(why, "FeatureMatchOptions.max_matches",
                   "must be at least min_matches (" + std::to_string(min_matches) + "), got " +
                       std::to_string(max_matches),
                   "use e.g. 40");
  }
  return true;
}

std::vector<FeatureMatch> MatchFeatures(const ImageFeatures& first, const ImageFeatures& second,
                                        const pose::CameraModel& camera,
                                        const FeatureMatchOptions& options,
                                        const std::string& first_name,
                                        const std::string& second_name) {
  RequireValid(options);
  // Step 2: ratio test both ways, mutual check.
  const std::vector<int> forward =
      RatioMatches(first.descriptors, second.descriptors, options.ratio);
  const std::vector<int> backward =
      RatioMatches(second.descriptors, first.descriptors, options.ratio);
  std::vector<FeatureMatch> candidates;
  std::vector<cv::Point2d> first_normalised, second_normalised;
  for (int i = 0; i < int(forward.size()); ++i) {
    const int j = forward[i];
    if (j < 0 || backward[j] != i) continue;
    FeatureMatch match;
    match.first_pixel = {first.keypoints[i].pt.x, first.keypoints[i].pt.y};
    match.second_pixel = {second.keypoints[j].pt.x, second.keypoints[j].pt.y};
    const auto a = pose::Undistort(camera, match.first_pixel);
    const auto b = pose::Undistort(camera, match.second_pixel);
    if (!a || !b) continue;
    match.first_ray = Eigen::Vector3d(a->x(), a->y(), 1.0).normalized();
    match.second_ray = Eigen::Vector3d(b->x(), b->y(), 1.0).normalized();
    match.distance = float(cv::norm(first.descriptors.row(i), second.descriptors.row(j),
                                    DescriptorNorm(first.descriptors)));
    candidates.push_back(match);
    first_normalised.emplace_back(a->x(), a->y());
    second_normalised.emplace_back(b->x(), b->y());
  }
  const auto refuse = [&](std::size_t found, const std::string& stage) {
    throw InputError(first_name, 0,
                     "only " + std::to_string(found) + " feature matches with " + second_name +
                         " " + stage + " (at least " + std::to_string(options.min_matches) +
                         " needed)",
                     "take the two images closer together, with more overlap and texture and a "
                     "translation between them, or use a target (--target target.yaml)");
  };
  if (int(candidates.size()) < std::max(options.min_matches, 5)) {
    refuse(candidates.size(), "pass the ratio and mutual checks");
  }
  // Step 3: essential-matrix RANSAC on normalised coordinates.
  const double focal = 0.5 * (camera.fx + camera.fy);
  const double threshold = 4.0 * std::sqrt(2.0) * options.pixel_sigma / focal;
  cv::Mat inlier_mask;
  const cv::Mat E =
      cv::findEssentialMat(first_normalised, second_normalised, cv::Mat::eye(3, 3, CV_64F),
                           cv::RANSAC, 0.999, threshold, inlier_mask);
  std::vector<FeatureMatch> inliers;
  if (!E.empty()) {
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      if (inlier_mask.at<unsigned char>(int(k))) inliers.push_back(candidates[k]);
    }
  }
  if (int(inliers.size()) < options.min_matches) {
    refuse(inliers.size(), "fit one essential matrix");
  }
  // Step 4: round robin over a grid of cells, best descriptor distance first in each cell.
  const int cells = std::max(1, int(std::ceil(std::sqrt(double(options.max_matches)))));
  const double width = std::max(1, first.size.width), height = std::max(1, first.size.height);
  std::stable_sort(
      inliers.begin(), inliers.end(),
      [](const FeatureMatch& a, const FeatureMatch& b) { return a.distance < b.distance; });
  std::map<int, int> taken_in_cell;
  std::vector<std::pair<int, int>> order;  // (rank in its cell, index)
  for (int k = 0; k < int(inliers.size()); ++k) {
    const int cx = std::clamp(int(inliers[k].first_pixel.x() / width * cells), 0, cells - 1);
    const int cy = std::clamp(int(inliers[k].first_pixel.y() / height * cells), 0, cells - 1);
    order.emplace_back(taken_in_cell[cy * cells + cx]++, k);
  }
  std::stable_sort(order.begin(), order.end());
  std::vector<FeatureMatch> out;
  for (const auto& [rank, k] : order) {
    if (int(out.size()) == options.max_matches) break;
    out.push_back(inliers[k]);
  }
  return out;
}

std::vector<std::vector<FeatureMatch>> MatchConsecutiveImages(
    const std::vector<std::filesystem::path>& paths, const std::vector<std::string>& names,
    const pose::CameraModel& camera, const FeatureMatchOptions& options, int threads) {
  RequireValid(options);
  if (names.size() != paths.size()) {
    throw std::invalid_argument("MatchConsecutiveImages: one name per path");
  }
  const int previous_threads = cv::getNumThreads();
  cv::setNumThreads(threads == 0 ? -1 : threads);  // -1: OpenCV's default, every core
  struct Restore {
    int threads;
    ~Restore() { cv::setNumThreads(threads); }
  } restore{previous_threads};
  // Runs `job(i)` for i in [0, n) in parallel; rethrows the first error in index order.
  const auto each = [](int n, const std::function<void(int)>& job) {
    std::vector<std::exception_ptr> errors(std::size_t(std::max(n, 0)));
    cv::parallel_for_(
        cv::Range(0, std::max(n, 0)),
        [&](const cv::Range& range) {
          for (int i = range.start; i < range.end; ++i) {
            try {
              job(i);
            } catch (...) {
              errors[std::size_t(i)] = std::current_exception();
            }
          }
        },
        double(std::max(n, 1)));
    for (const std::exception_ptr& error : errors) {
      if (error) std::rethrow_exception(error);
    }
  };
  const int n = int(paths.size());
  std::vector<ImageFeatures> features(std::size_t(std::max(n, 0)));
  each(n, [&](int i) {
    const cv::Mat gray = ReadGrayImage(paths[std::size_t(i)].string(), kMinDetectionSide);
    if (camera.width > 0 && (gray.cols != camera.width || gray.rows != camera.height)) {
      throw InputError(paths[std::size_t(i)].string(), 0,
                       "the image is " + std::to_string(gray.cols) + "x" +
                           std::to_string(gray.rows) + " but the intrinsics are for " +
                           std::to_string(camera.width) + "x" + std::to_string(camera.height),
                       "give the intrinsics of this camera at this resolution");
    }
    features[std::size_t(i)] = DetectFeatures(gray, 8000, options.kind);
  });
  std::vector<std::vector<FeatureMatch>> matches(std::size_t(std::max(n - 1, 0)));
  each(n - 1, [&](int k) {
    const std::size_t a = std::size_t(k), b = a + 1;
    matches[a] = MatchFeatures(features[a], features[b], camera, options, names[a], names[b]);
  });
  return matches;
}

}  // namespace hecal::vision
