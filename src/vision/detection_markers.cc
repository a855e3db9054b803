// ChArUco, ArUco grid and single ArUco marker detection with OpenCV 4.6's contrib aruco module
// (detection.h).
#include <algorithm>
#include <opencv2/aruco.hpp>
#include <opencv2/aruco/charuco.hpp>

#include "detection_internal.h"
#include "hecal/core/error.h"

namespace hecal::vision::internal {
namespace {

// ChArUco corner refinement: the edge band's half-width as a fraction of the white margin between
// a square's edge and its marker ((square − marker) / 2).
constexpr double kCharucoBandFraction = 0.5;

struct Markers {
  std::vector<std::vector<cv::Point2f>> corners;
  std::vector<int> ids;
  std::string summary;  // "12 markers", plus repeated ids and ids not on the board
};

// Detects the markers of `board`, recovers missed ones with the board layout and drops ids seen
// more than once or not on the board (named in the summary).
Markers DetectBoardMarkers(const cv::Mat& gray, const cv::Ptr<cv::aruco::Board>& board) {
  // Corners are refined afterwards (RefineMarkerCorners); the marker corners only seed them.
  const cv::Ptr<cv::aruco::DetectorParameters> parameters = cv::aruco::DetectorParameters::create();
  Markers markers;
  std::vector<std::vector<cv::Point2f>> rejected;
  cv::aruco::detectMarkers(gray, board->dictionary, markers.corners, markers.ids, parameters,
                           rejected);
  cv::aruco::refineDetectedMarkers(gray, board, markers.corners, markers.ids, rejected,
                                   cv::noArray(), cv::noArray(), 10.f, 3.f, true, cv::noArray(),
                                   parameters);
  size_t kept = 0;
  std::vector<int> others;
  for (size_t k = 0; k < markers.ids.size(); ++k) {
    if (std::find(board->ids.begin(), board->ids.end(), markers.ids[k]) == board->ids.end()) {
      others.push_back(markers.ids[k]);
      continue;
    }
    markers.ids[kept] = markers.ids[k];
    markers.corners[kept] = markers.corners[k];
    ++kept;
  }
  markers.ids.resize(kept);
  markers.corners.resize(kept);
  markers.summary = KeepUniqueMarkers(&markers.ids, &markers.corners, "markers", others);
  return markers;
}

}  // namespace

cv::Ptr<cv::aruco::Dictionary> ArucoDictionary(const std::string& name) {
  const std::span<const pose::MarkerDictionary> dictionaries = pose::ArucoDictionaries();
  for (size_t k = 0; k < dictionaries.size(); ++k) {
    if (dictionaries[k].name == name) {
      return cv::aruco::getPredefinedDictionary(static_cast<int>(k));
    }
  }
  throw InputError("target", 0, "unknown ArUco dictionary '" + name + "'",
                   "use one of OpenCV's predefined dictionaries, e.g. DICT_5X5_250");
}

Detection DetectCharuco(const cv::Mat& gray, const pose::TargetSpec& target,
                        const DetectOptions& options) {
  const cv::Ptr<cv::aruco::CharucoBoard> board = cv::aruco::CharucoBoard::create(
      target.cols, target.rows, static_cast<float>(target.square),
      static_cast<float>(target.marker), ArucoDictionary(target.dictionary));
  const Markers markers = DetectBoardMarkers(gray, board);
  std::vector<ImagePoint> points;
  if (!markers.ids.empty()) {
    std::vector<cv::Point2f> corners;
    std::vector<int> ids;
    cv::aruco::interpolateCornersCharuco(markers.corners, markers.ids, gray, board, corners, ids);
    // OpenCV 4.6 returns these corners 0.5 px off (it shifts cornerSubPix's result by
    // (+0.5, +0.5); opencv_contrib PR 3024, fixed in opencv PR 28380): they are refined again,
    // from the edges between the squares, in OpenCV's pixel convention.
    std::vector<std::optional<cv::Point2f>> grid(
        static_cast<size_t>((target.cols - 1) * (target.rows - 1)));
    for (size_t k = 0; k < ids.size(); ++k) grid[static_cast<size_t>(ids[k])] = corners[k];
    RefineSaddleCorners(
        gray, target.cols - 1, target.rows - 1,
        kCharucoBandFraction * (target.square - target.marker) / 2.0 / target.square, &grid);
    for (size_t k = 0; k < ids.size(); ++k) corners[k] = *grid[static_cast<size_t>(ids[k])];
    for (size_t k = 0; k < ids.size(); ++k) {
      points.push_back({ids[k], Eigen::Vector2d(corners[k].x, corners[k].y)});
    }
  }
  return MarkerDetection(gray, target, options, std::move(points), markers.summary);
}

Detection DetectArucoMarkers(const cv::Mat& gray, const pose::TargetSpec& target,
                             const DetectOptions& options,
                             const std::optional<pose::CameraModel>& camera) {
  const MarkerGrid grid = MarkerGridOf(target);
  // GridBoard::create requires a positive separation; a single marker has no neighbour, and any
  // separation gives the same 1 × 1 board.
  const double separation = grid.spacing > 0.0 ? grid.spacing : grid.marker;
  const cv::Ptr<cv::aruco::GridBoard> board = cv::aruco::GridBoard::create(
      grid.cols, grid.rows, static_cast<float>(grid.marker), static_cast<float>(separation),
      ArucoDictionary(target.dictionary), grid.first_id);
  Markers markers = DetectBoardMarkers(gray, board);
  RefineMarkerCorners(gray, board->dictionary->markerSize + 2, camera, &markers.corners);
  std::vector<ImagePoint> points = GridMarkerPoints(markers.ids, markers.corners, grid.first_id);
  return MarkerDetection(gray, target, options, std::move(points), markers.summary);
}

}  // namespace hecal::vision::internal
