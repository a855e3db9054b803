// The gradient-based edge width (detection.h, "Sharpness") and point spacing.
#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "detection_internal.h"

namespace hecal::vision::internal {
namespace {

// Window half-size around a point, as a fraction of the distance to its nearest neighbour.
constexpr double kWindowFraction = 0.45;
// Percentiles of the grey levels that define the contrast.
constexpr double kDarkPercentile = 0.05;
constexpr double kBrightPercentile = 0.95;

double Percentile(std::vector<float>* values, double fraction) {
  const auto it = values->begin() + static_cast<long>(fraction * (values->size() - 1));
  std::nth_element(values->begin(), it, values->end());
  return *it;
}

}  // namespace

double SmallestSpacing(const std::vector<cv::Point2f>& points) {
  double smallest = std::numeric_limits<double>::infinity();
  for (size_t a = 0; a < points.size(); ++a) {
    for (size_t b = a + 1; b < points.size(); ++b) {
      smallest = std::min(smallest, static_cast<double>(cv::norm(points[a] - points[b])));
    }
  }
  return smallest;
}

double MeanEdgeWidth(const cv::Mat& gray, const std::vector<cv::Point2f>& points) {
  if (points.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  // Sobel 3×3 scaled by 1/8: the central difference of the [1 2 1]/4-smoothed image, in grey
  // levels per pixel.
  cv::Mat gx, gy, magnitude;
  cv::Sobel(gray, gx, CV_32F, 1, 0, 3, 1.0 / 8.0);
  cv::Sobel(gray, gy, CV_32F, 0, 1, 3, 1.0 / 8.0);
  cv::magnitude(gx, gy, magnitude);
  double sum = 0.0;
  int count = 0;
  std::vector<float> levels, gradients;
  for (size_t k = 0; k < points.size(); ++k) {
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t other = 0; other < points.size(); ++other) {
      if (other != k)
        nearest = std::min(nearest, static_cast<double>(cv::norm(points[k] - points[other])));
    }
    const int half = std::max(2, static_cast<int>(kWindowFraction * nearest));
    const cv::Rect window =
        cv::Rect(static_cast<int>(std::lround(points[k].x)) - half,
                 static_cast<int>(std::lround(points[k].y)) - half, 2 * half + 1, 2 * half + 1) &
        cv::Rect(0, 0, gray.cols, gray.rows);
    if (window.area() <= half) continue;
    levels.clear();
    gradients.clear();
    for (int v = window.y; v < window.y + window.height; ++v) {
      for (int u = window.x; u < window.x + window.width; ++u) {
        levels.push_back(gray.at<uchar>(v, u));
        gradients.push_back(magnitude.at<float>(v, u));
      }
    }
    const double contrast =
        Percentile(&levels, kBrightPercentile) - Percentile(&levels, kDarkPercentile);
    // The half-th largest gradient: the ridge of an edge across the window has about 2·half
    // pixels near its peak, so a few noisy pixels do not set the peak.
    const auto peak = gradients.begin() + (half - 1);
    std::nth_element(gradients.begin(), peak, gradients.end(), std::greater<float>());
    if (contrast > 0.0 && *peak > 0.0f) {
      sum += contrast / *peak;
      ++count;
    }
  }
  return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace hecal::vision::internal
