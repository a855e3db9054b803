// The chessboard sizes one inner corner off a description: see chessboard_size_probe.h.
#include "hecal/vision/chessboard_size_probe.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "hecal/vision/chessboard_extent.h"

namespace hecal::vision {
namespace {

constexpr double kProbeSide = 1000.0;  // px: the image is searched at most this long

// Is the board whole in the image: every corner kBorderSquares mean corner spacings inside it?
bool WellInside(const cv::Mat& gray, const std::vector<cv::Point2f>& corners, cv::Size size) {
  double spacing = 0.0;
  int pairs = 0;
  for (int r = 0; r < size.height; ++r) {
    for (int c = 0; c + 1 < size.width; ++c) {
      spacing += cv::norm(corners[static_cast<std::size_t>(r * size.width + c + 1)] -
                          corners[static_cast<std::size_t>(r * size.width + c)]);
      ++pairs;
    }
  }
  const double margin = kBorderSquares * spacing / std::max(pairs, 1);
  return std::all_of(corners.begin(), corners.end(), [&](const cv::Point2f& p) {
    return p.x >= margin && p.y >= margin && p.x <= gray.cols - 1 - margin &&
           p.y <= gray.rows - 1 - margin;
  });
}

}  // namespace

std::optional<cv::Size> ProbeChessboardSize(const cv::Mat& gray, int cols, int rows) {
  const cv::Size sizes[] = {{cols - 1, rows}, {cols + 1, rows},     {cols, rows - 1},
                            {cols, rows + 1}, {cols - 1, rows - 1}, {cols + 1, rows + 1}};
  const double scale = std::min(1.0, kProbeSide / std::max(gray.cols, gray.rows));
  cv::Mat small = gray;
  if (scale < 1.0) cv::resize(gray, small, cv::Size(), scale, scale, cv::INTER_AREA);
  for (const cv::Size& size : sizes) {
    if (size.width < 3 || size.height < 3) continue;
    std::vector<cv::Point2f> corners;
    if (!cv::findChessboardCorners(small, size, corners,
                                   cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE)) {
      continue;
    }
    for (cv::Point2f& p : corners) p *= static_cast<float>(1.0 / scale);
    if (!WellInside(gray, corners, size)) continue;
    std::vector<Eigen::Vector2d> pixels;
    for (const cv::Point2f& p : corners) pixels.emplace_back(p.x, p.y);
    if (MeasureChessboardExtent(gray, size.width, size.height, pixels).larger()) continue;
    return size;
  }
  return std::nullopt;
}

}  // namespace hecal::vision
