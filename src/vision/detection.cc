// DetectTarget: checks, the grid detectors (chessboard, circle grids) and the shared finishing of
// marker detections (see detection.h for the rules).
#include "hecal/vision/detection.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "detection_internal.h"
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/vision/order_consistency.h"

namespace hecal::vision {
namespace {

// Edge band of the classic detector's corner refinement (detection_edges.cc), as a fraction of the
// corner spacing. On data/rwhe-kuka2 it leaves 0.064–0.10 px RMS reprojection error (as
// findChessboardCornersSB with ACCURACY: 0.061–0.10 px; cornerSubPix: 0.09–0.21 px).
constexpr double kChessboardBand = 0.1;
// Points below which a partial detection is reported as giving a weak pose (detection.h).
constexpr int kPreferredPoints = 6;
// Circle centre refinement: iterations and convergence (px), and the grey level taken as paper.
constexpr int kCentroidIterations = 20;
constexpr double kCentroidTolerance = 1e-4;
constexpr double kPaperPercentile = 0.9;

std::string GridName(const pose::TargetSpec& target) {
  return std::to_string(target.cols) + "x" + std::to_string(target.rows) + " " +
         std::string(pose::TargetTypeName(target.type));
}

Detection NotFound(const pose::TargetSpec& target, std::string message) {
  Detection detection;
  detection.total_points = pose::PointCount(target);
  detection.message = std::move(message);
  return detection;
}

// The detection of a complete grid in canonical order (or a half turn of it, kSymmetric).
Detection GridDetection(const pose::TargetSpec& target, const std::vector<cv::Point2f>& grid,
                        GridOrder order, double sharpness, const std::string& method) {
  if (order == GridOrder::kInvalid) {
    return NotFound(target, GridName(target) + ": " + method +
                                " returned a grid whose extreme points are (nearly) on one line; "
                                "not used");
  }
  Detection detection;
  detection.total_points = pose::PointCount(target);
  for (size_t k = 0; k < grid.size(); ++k) {
    detection.points.push_back({static_cast<int>(k), Eigen::Vector2d(grid[k].x, grid[k].y)});
  }
  detection.sharpness = sharpness;
  detection.message = GridName(target) + ": " + std::to_string(grid.size()) + " of " +
                      std::to_string(detection.total_points) + " points (" + method + ")";
  if (order == GridOrder::kUnique) {
    detection.status = DetectionStatus::kFound;
    detection.order = PointOrder::kPattern;
  } else {
    detection.status = DetectionStatus::kAmbiguous;
    detection.order = PointOrder::kImage;
    detection.message +=
        "; the pattern looks the same after a half turn, so the order is fixed only by the image "
        "rule (make a set of images consistent with ResolveOrder)";
  }
  return detection;
}

// findChessboardCorners + edge refinement first: on data/rwhe-kuka2 it takes 0.01 s + the
// refinement per 1920x1200 image against 2.4 s for findChessboardCornersSB with ACCURACY, with the
// same corner accuracy (kChessboardBand). The SB detector stays as the fallback: it finds boards
// the classic detector misses (blur, uneven light, boards cut by the image border's margin).
bool FindClassicChessboard(const cv::Mat& gray, const pose::TargetSpec& target,
                           std::vector<cv::Point2f>* corners) {
  if (!cv::findChessboardCorners(gray, cv::Size(target.cols, target.rows), *corners,
                                 cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE)) {
    return false;
  }
  std::vector<std::optional<cv::Point2f>> grid(corners->begin(), corners->end());
  internal::RefineSaddleCorners(gray, target.cols, target.rows, kChessboardBand, &grid);
  for (size_t k = 0; k < corners->size(); ++k) (*corners)[k] = *grid[k];
  return true;
}

Detection DetectChessboard(const cv::Mat& gray, const pose::TargetSpec& target,
                           const DetectOptions& options) {
  const cv::Size size(target.cols, target.rows);
  std::vector<cv::Point2f> corners;
  std::string method = "findChessboardCorners + edge refinement";
  bool found = options.chessboard_fast_first && FindClassicChessboard(gray, target, &corners);
  if (!found) {
    method = "findChessboardCornersSB";
    found = cv::findChessboardCornersSB(gray, size, corners,
                                        cv::CALIB_CB_EXHAUSTIVE | cv::CALIB_CB_ACCURACY);
  }
  if (!found) {
    return NotFound(target, "no complete " + GridName(target) + " (inner corners) found" +
                                (options.chessboard_fast_first
                                     ? " by findChessboardCorners or findChessboardCornersSB"
                                     : " by findChessboardCornersSB"));
  }
  const GridOrder order = CanonicalGridOrder(gray, target, &corners);
  const double sharpness = cv::estimateChessboardSharpness(gray, size, corners)[0];
  return GridDetection(target, corners, order, sharpness, method);
}

// Moves each centre to the grey-level centroid of its dark blob (detection.h).
void RefineCircleCentres(const cv::Mat& gray, std::vector<cv::Point2f>* centres) {
  const double radius = 0.5 * internal::SmallestSpacing(*centres);
  std::vector<std::pair<cv::Point2d, double>> window;  // pixel centre, grey level
  std::vector<double> levels;
  for (cv::Point2f& centre : *centres) {
    cv::Point2d c = centre;
    for (int iteration = 0; iteration < kCentroidIterations; ++iteration) {
      window.clear();
      levels.clear();
      const int u0 = std::max(0, static_cast<int>(std::floor(c.x - radius)));
      const int u1 = std::min(gray.cols - 1, static_cast<int>(std::ceil(c.x + radius)));
      const int v0 = std::max(0, static_cast<int>(std::floor(c.y - radius)));
      const int v1 = std::min(gray.rows - 1, static_cast<int>(std::ceil(c.y + radius)));
      for (int v = v0; v <= v1; ++v) {
        for (int u = u0; u <= u1; ++u) {
          const cv::Point2d p(u, v);
          if (cv::norm(p - c) > radius) continue;
          const double level = gray.at<uchar>(v, u);
          window.emplace_back(p, level);
          levels.push_back(level);
        }
      }
      if (levels.empty()) break;
      const auto paper_it =
          levels.begin() + static_cast<long>(kPaperPercentile * (levels.size() - 1));
      std::nth_element(levels.begin(), paper_it, levels.end());
      const double paper = *paper_it;
      cv::Point2d moment(0.0, 0.0);
      double mass = 0.0;
      for (const auto& [p, level] : window) {
        const double w = std::max(0.0, paper - level);
        moment += w * p;
        mass += w;
      }
      if (!(mass > 0.0)) break;
      const cv::Point2d next = moment / mass;
      const double shift = cv::norm(next - c);
      c = next;
      if (shift < kCentroidTolerance) break;
    }
    centre = cv::Point2f(static_cast<float>(c.x), static_cast<float>(c.y));
  }
}

Detection DetectCircles(const cv::Mat& gray, const pose::TargetSpec& target) {
  const cv::Size size(target.cols, target.rows);
  cv::SimpleBlobDetector::Params params;
  params.minArea = 10.0f;
  params.maxArea = static_cast<float>(gray.total()) / static_cast<float>(target.cols * target.rows);
  const cv::Ptr<cv::FeatureDetector> blobs = cv::SimpleBlobDetector::create(params);
  const bool symmetric = target.type == pose::TargetType::kCircles;
  const int flags = symmetric ? cv::CALIB_CB_SYMMETRIC_GRID : cv::CALIB_CB_ASYMMETRIC_GRID;
  std::vector<cv::Point2f> centres;
  // OpenCV 4.6's default grid finder misses grids turned by about a quarter turn in the image
  // (a 7 × 5 grid rolled 60°–120°, measured); its clustering finder does not.
  if (!cv::findCirclesGrid(gray, size, centres, flags, blobs) &&
      !cv::findCirclesGrid(gray, size, centres, flags | cv::CALIB_CB_CLUSTERING, blobs)) {
    return NotFound(target, "no complete " + GridName(target) +
                                " found by findCirclesGrid (default and clustering)");
  }
  const GridOrder order = CanonicalGridOrder(gray, target, &centres);
  RefineCircleCentres(gray, &centres);
  return GridDetection(target, centres, order, internal::MeanEdgeWidth(gray, centres),
                       "findCirclesGrid + grey-level centroids");
}

// The camera must be usable for undistortion and be this image's (detection.h: errors).
void RequireCameraOf(const pose::CameraModel& camera, const cv::Size& size) {
  bool finite = std::isfinite(camera.cx) && std::isfinite(camera.cy);
  for (const double coefficient : camera.distortion) finite = finite && std::isfinite(coefficient);
  if (!(camera.fx > 0.0) || !(camera.fy > 0.0) || !std::isfinite(camera.fx) ||
      !std::isfinite(camera.fy) || !finite) {
    throw InputError("camera", 0,
                     "the intrinsics are not usable (fx, fy must be positive, every "
                     "value finite)",
                     "pass the camera's calibrated intrinsics");
  }
  if (camera.width > 0 && (camera.width != size.width || camera.height != size.height)) {
    throw InputError("camera", 0,
                     "the intrinsics are for " + std::to_string(camera.width) + "x" +
                         std::to_string(camera.height) + " images but the image is " +
                         std::to_string(size.width) + "x" + std::to_string(size.height),
                     "pass the intrinsics of this camera at this resolution");
  }
}

}  // namespace

std::string_view DetectionStatusName(DetectionStatus status) {
  switch (status) {
    case DetectionStatus::kFound:
      return "found";
    case DetectionStatus::kPartial:
      return "partial";
    case DetectionStatus::kNotFound:
      return "not_found";
    case DetectionStatus::kAmbiguous:
      return "ambiguous";
  }
  return "unknown";
}

std::string_view PointOrderName(PointOrder order) {
  switch (order) {
    case PointOrder::kNone:
      return "none";
    case PointOrder::kMarkers:
      return "markers";
    case PointOrder::kPattern:
      return "pattern";
    case PointOrder::kImage:
      return "image";
    case PointOrder::kReference:
      return "reference";
    case PointOrder::kConsistency:
      return "consistency";
  }
  return "unknown";
}

bool DetectOptions::IsValid(std::string* why) const {
  if (min_points < 4) {
    return Invalid(why, "DetectOptions.min_points",
                   "must be at least 4, got " + std::to_string(min_points),
                   "ask for 4 or more points (a planar pose needs 4)");
  }
  if (apriltag_max_hamming < 0 || apriltag_max_hamming > 2) {
    return Invalid(why, "DetectOptions.apriltag_max_hamming",
                   "must be 0, 1 or 2, got " + std::to_string(apriltag_max_hamming),
                   "give the corrected bits libapriltag may accept (default 1)");
  }
  if (!(apriltag_decimate >= 1.0) || !std::isfinite(apriltag_decimate)) {
    return Invalid(why, "DetectOptions.apriltag_decimate", "must be a finite number of at least 1",
                   "give 1 for full resolution, 2 for half");
  }
  return true;
}

namespace internal {

void RequireUsableTarget(const pose::TargetSpec& target) {
  if (const std::optional<pose::TargetProblem> problem = pose::CheckTarget(target)) {
    throw InputError("target", 0, problem->problem, problem->fix);
  }
}

cv::Mat ToGray(const cv::Mat& image) {
  if (image.empty()) throw InputError("image", 0, "the image is empty", "pass a decoded image");
  if (image.depth() != CV_8U ||
      (image.channels() != 1 && image.channels() != 3 && image.channels() != 4)) {
    throw InputError("image", 0,
                     "unsupported pixel format (" + std::to_string(image.channels()) +
                         " channels, depth code " + std::to_string(image.depth()) + ")",
                     "pass an 8-bit grey, BGR or BGRA image");
  }
  if (image.channels() == 1) return image;
  cv::Mat gray;
  cv::cvtColor(image, gray, image.channels() == 3 ? cv::COLOR_BGR2GRAY : cv::COLOR_BGRA2GRAY);
  return gray;
}

std::string KeepUniqueMarkers(std::vector<int>* ids, std::vector<std::vector<cv::Point2f>>* corners,
                              const std::string& noun, const std::vector<int>& others) {
  std::vector<int> repeated;
  for (const int id : *ids) {
    if (std::count(ids->begin(), ids->end(), id) > 1 &&
        std::find(repeated.begin(), repeated.end(), id) == repeated.end()) {
      repeated.push_back(id);
    }
  }
  size_t kept = 0;
  for (size_t k = 0; k < ids->size(); ++k) {
    if (std::find(repeated.begin(), repeated.end(), (*ids)[k]) != repeated.end()) continue;
    (*ids)[kept] = (*ids)[k];
    (*corners)[kept] = (*corners)[k];
    ++kept;
  }
  ids->resize(kept);
  corners->resize(kept);
  std::string summary = std::to_string(kept) + " " + noun;
  const auto list = [&summary](const std::string& what, const std::vector<int>& list_ids) {
    if (list_ids.empty()) return;
    summary += " (" + what + ":";
    for (const int id : list_ids) {
      summary += ' ';
      summary += std::to_string(id);
    }
    summary += ")";
  };
  list("ids seen more than once, dropped", repeated);
  std::vector<int> other_ids = others;
  std::sort(other_ids.begin(), other_ids.end());
  other_ids.erase(std::unique(other_ids.begin(), other_ids.end()), other_ids.end());
  list("other ids in view, not the target's, ignored", other_ids);
  return summary;
}

MarkerGrid MarkerGridOf(const pose::TargetSpec& target) {
  MarkerGrid grid;
  if (pose::IsSingleTag(target.type)) {
    grid.marker = target.size;
    grid.first_id = target.id;
    grid.origin = cv::Point2d(-target.size / 2.0, -target.size / 2.0);
    return grid;
  }
  grid.cols = target.cols;
  grid.rows = target.rows;
  grid.marker = target.marker;
  grid.spacing = target.spacing;
  grid.first_id = target.first_id;
  return grid;
}

std::vector<ImagePoint> GridMarkerPoints(const std::vector<int>& ids,
                                         const std::vector<std::vector<cv::Point2f>>& corners,
                                         int first_id) {
  std::vector<ImagePoint> points;
  for (size_t k = 0; k < ids.size(); ++k) {
    const int m = ids[k] - first_id;
    for (int corner = 0; corner < 4; ++corner) {
      const cv::Point2f& p = corners[k][static_cast<size_t>(corner)];
      points.push_back({4 * m + corner, Eigen::Vector2d(p.x, p.y)});
    }
  }
  return points;
}

Detection MarkerDetection(const cv::Mat& gray, const pose::TargetSpec& target,
                          const DetectOptions& options, std::vector<ImagePoint> points,
                          const std::string& summary) {
  std::sort(points.begin(), points.end(),
            [](const ImagePoint& a, const ImagePoint& b) { return a.id < b.id; });
  Detection detection;
  detection.total_points = pose::PointCount(target);
  const std::string count =
      std::to_string(points.size()) + " of " + std::to_string(detection.total_points) + " points";
  detection.message =
      std::string(pose::TargetTypeName(target.type)) + ": " + summary + ", " + count;
  if (points.empty()) return detection;
  if (static_cast<int>(points.size()) < detection.total_points) {
    if (!options.allow_partial) {
      detection.message += "; partial detections are not allowed";
      return detection;
    }
    if (static_cast<int>(points.size()) < options.min_points) {
      detection.message += "; fewer than " + std::to_string(options.min_points) + " points";
      return detection;
    }
    // All object points on one line leave the rotation about that line free.
    const std::vector<pose::ObjectPoint> object = pose::ObjectPoints(target);
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const ImagePoint& p : points) mean += object[static_cast<size_t>(p.id)].position.head<2>();
    mean /= static_cast<double>(points.size());
    Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
    for (const ImagePoint& p : points) {
      const Eigen::Vector2d d = object[static_cast<size_t>(p.id)].position.head<2>() - mean;
      scatter += d * d.transpose();
    }
    const Eigen::Vector2d spread =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(scatter).eigenvalues();
    if (!(spread(0) > 1e-10 * spread(1))) {
      detection.message += "; the points lie on one line of the board (no pose)";
      return detection;
    }
    detection.status = DetectionStatus::kPartial;
    if (static_cast<int>(points.size()) < kPreferredPoints) {
      detection.message +=
          "; fewer than " + std::to_string(kPreferredPoints) + " points: a weak pose";
    }
  } else {
    detection.status = DetectionStatus::kFound;
  }
  detection.order = PointOrder::kMarkers;
  std::vector<cv::Point2f> pixels;
  for (const ImagePoint& p : points) {
    pixels.emplace_back(static_cast<float>(p.pixel.x()), static_cast<float>(p.pixel.y()));
  }
  detection.sharpness = MeanEdgeWidth(gray, pixels);
  detection.points = std::move(points);
  return detection;
}

}  // namespace internal

Detection DetectTarget(const cv::Mat& image, const pose::TargetSpec& target,
                       const DetectOptions& options,
                       const std::optional<pose::CameraModel>& camera) {
  RequireValid(options);
  internal::RequireUsableTarget(target);
  const bool grid =
      target.type == pose::TargetType::kChessboard || target.type == pose::TargetType::kCircles;
  if (grid && target.cols == target.rows) {
    throw InputError("target", 0,
                     "a square " + std::string(pose::TargetTypeName(target.type)) + " (" +
                         std::to_string(target.cols) + " x " + std::to_string(target.rows) +
                         ") looks the same after a quarter turn, so its point order is ambiguous",
                     "use a board with different numbers of points along x and y");
  }
  const cv::Mat gray = internal::ToGray(image);
  if (camera) RequireCameraOf(*camera, gray.size());
  switch (target.type) {
    case pose::TargetType::kChessboard:
      return DetectChessboard(gray, target, options);
    case pose::TargetType::kCircles:
    case pose::TargetType::kAsymmetricCircles:
      return DetectCircles(gray, target);
    case pose::TargetType::kCharuco:
      return internal::DetectCharuco(gray, target, options);
    case pose::TargetType::kArucoGrid:
    case pose::TargetType::kAruco:
      return internal::DetectArucoMarkers(gray, target, options, camera);
    case pose::TargetType::kAprilTagGrid:
    case pose::TargetType::kAprilTag:
      return internal::DetectAprilTags(gray, target, options, camera);
  }
  return NotFound(target, "unknown target type");
}

}  // namespace hecal::vision
