// Squares of the checker pattern beyond a detected chessboard: see chessboard_extent.h.
#include "hecal/vision/chessboard_extent.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <utility>

namespace hecal::vision {
namespace {

constexpr int kFitLines = 3;               // corner lines the local homography is fitted to
constexpr int kMinRingSquares = 3;         // squares of a ring in the image to judge it
constexpr double kMatchingFraction = 0.8;  // of those, with the colour of the checker parity
constexpr double kSampleRadius = 0.2;      // of a square's side
constexpr double kMixedFraction = 0.65;    // below: the squares do not alternate
constexpr double kMixedContrast = 0.25;    // below: the parities' levels barely differ
constexpr double kCheckerContrast = 0.5;   // at least: a checker pattern (walk made)
constexpr int kMaxSteps = 1000;            // pose/target.h bounds cols, rows by 1000

using Grid = std::map<std::pair<int, int>, cv::Point2d>;  // (column, row) → pixel

// Mean grey level in a disc, or nullopt when the disc leaves the image.
std::optional<double> DiscMean(const cv::Mat& gray, const cv::Point2d& centre, double radius) {
  const int u0 = static_cast<int>(std::floor(centre.x - radius));
  const int u1 = static_cast<int>(std::ceil(centre.x + radius));
  const int v0 = static_cast<int>(std::floor(centre.y - radius));
  const int v1 = static_cast<int>(std::ceil(centre.y + radius));
  if (!(u0 >= 0 && v0 >= 0 && u1 < gray.cols && v1 < gray.rows)) return std::nullopt;
  double sum = 0.0;
  int count = 0;
  for (int v = v0; v <= v1; ++v) {
    for (int u = u0; u <= u1; ++u) {
      if (std::hypot(u - centre.x, v - centre.y) > radius) continue;
      sum += gray.at<uchar>(v, u);
      ++count;
    }
  }
  if (count == 0) return std::nullopt;
  return sum / count;
}

int Parity(int i, int j) {
  return ((i + j) % 2 + 2) % 2;
}

cv::Point2d Apply(const cv::Matx33d& H, double x, double y) {
  const cv::Vec3d p = H * cv::Vec3d(x, y, 1.0);
  return {p[0] / p[2], p[1] / p[2]};
}

// The grey levels of the checker pattern at the detected corners (chessboard_extent.h): the mean
// level of the grid's inner squares of each parity (each centre the mean of its 4 corners), the
// fraction of those squares nearer their own parity's level than the other's, and the contrast:
// the difference of the two levels over the spread of the grey levels (5th to 95th percentile)
// in the corners' bounding box. NaN fraction and contrast when a parity has no square in view.
struct Checker {
  double level[2] = {0.0, 0.0};
  double fraction = std::numeric_limits<double>::quiet_NaN();
  double contrast = std::numeric_limits<double>::quiet_NaN();
};

// The grey level below which `share` of the pixels in the corners' bounding box lie.
double Percentile(const cv::Mat& gray, const Grid& grid, double share) {
  double u0 = gray.cols, v0 = gray.rows, u1 = 0.0, v1 = 0.0;
  for (const auto& [key, p] : grid) {
    u0 = std::min(u0, p.x);
    v0 = std::min(v0, p.y);
    u1 = std::max(u1, p.x);
    v1 = std::max(v1, p.y);
  }
  const cv::Rect box =
      cv::Rect(
          cv::Point(static_cast<int>(std::floor(u0)), static_cast<int>(std::floor(v0))),
          cv::Point(static_cast<int>(std::ceil(u1)) + 1, static_cast<int>(std::ceil(v1)) + 1)) &
      cv::Rect(0, 0, gray.cols, gray.rows);
  if (box.empty()) return std::numeric_limits<double>::quiet_NaN();
  long histogram[256] = {};
  for (int v = box.y; v < box.y + box.height; ++v) {
    for (int u = box.x; u < box.x + box.width; ++u) ++histogram[gray.at<uchar>(v, u)];
  }
  const double wanted = share * static_cast<double>(box.area());
  long below = 0;
  for (int level = 0; level < 256; ++level) {
    below += histogram[level];
    if (static_cast<double>(below) >= wanted) return level;
  }
  return 255.0;
}

Checker MeasureChecker(const cv::Mat& gray, const Grid& grid, int cols, int rows) {
  Checker checker;
  std::vector<std::pair<int, double>> squares;  // parity, mean
  double sum[2] = {0.0, 0.0};
  int count[2] = {0, 0};
  for (int r = 0; r + 1 < rows; ++r) {
    for (int c = 0; c + 1 < cols; ++c) {
      const cv::Point2d& a = grid.at({c, r});
      const cv::Point2d& b = grid.at({c + 1, r});
      const cv::Point2d& d = grid.at({c, r + 1});
      const cv::Point2d centre = 0.25 * (a + b + d + grid.at({c + 1, r + 1}));
      const double side = 0.5 * (cv::norm(b - a) + cv::norm(d - a));
      const std::optional<double> mean = DiscMean(gray, centre, kSampleRadius * side);
      if (!mean) continue;
      squares.emplace_back(Parity(c, r), *mean);
      sum[Parity(c, r)] += *mean;
      ++count[Parity(c, r)];
    }
  }
  if (count[0] == 0 || count[1] == 0) return checker;
  checker.level[0] = sum[0] / count[0];
  checker.level[1] = sum[1] / count[1];
  const auto matching = std::count_if(squares.begin(), squares.end(), [&](const auto& square) {
    const auto& [parity, mean] = square;
    return std::abs(mean - checker.level[parity]) < std::abs(mean - checker.level[1 - parity]);
  });
  checker.fraction = static_cast<double>(matching) / static_cast<double>(squares.size());
  const double spread = Percentile(gray, grid, 0.95) - Percentile(gray, grid, 0.05);
  checker.contrast = spread > 0.0 ? std::abs(checker.level[0] - checker.level[1]) / spread : 0.0;
  return checker;
}

// The walk away from one side (chessboard_extent.h). `axis` 0 walks along x (columns), 1 along
// y (rows); `sign` −1 walks before the first line, +1 after the last. `level` holds the mean
// grey level of the inner squares of each parity. Returns the lines found and sets `*border`
// when the walk stopped at the image border.
int Walk(const cv::Mat& gray, Grid grid, int cols, int rows, int axis, int sign,
         const double level[2], bool* border) {
  const int lines = axis == 0 ? cols : rows;   // corner lines along the walk
  const int across = axis == 0 ? rows : cols;  // corners on each line
  const auto key = [axis](int along, int other) {
    return axis == 0 ? std::make_pair(along, other) : std::make_pair(other, along);
  };
  int frontier = sign < 0 ? 0 : lines - 1;
  int found = 0;
  for (int step = 0; step < kMaxSteps; ++step) {
    std::vector<cv::Point2d> from, to;
    for (int k = 0; k < kFitLines; ++k) {
      for (int b = 0; b < across; ++b) {
        const auto it = grid.find(key(frontier - sign * k, b));
        if (it == grid.end()) continue;
        from.emplace_back(it->first.first, it->first.second);
        to.push_back(it->second);
      }
    }
    if (from.size() < 4) return found;
    const cv::Mat fitted = cv::findHomography(from, to, 0);
    if (fitted.empty()) return found;
    const cv::Matx33d H(fitted);

    // The ring beyond the next line of corners: centres at frontier + 1.5·sign along the walk.
    const double along = frontier + 1.5 * sign;
    int in_view = 0, matching = 0;
    double ring_sum[2] = {0.0, 0.0};
    int ring_count[2] = {0, 0};
    for (int b = -1; b < across; ++b) {
      const double x = axis == 0 ? along : b + 0.5;
      const double y = axis == 0 ? b + 0.5 : along;
      const cv::Point2d centre = Apply(H, x, y);
      const double side = cv::norm(Apply(H, x + 0.5, y) - Apply(H, x - 0.5, y));
      const std::optional<double> mean = DiscMean(gray, centre, kSampleRadius * side);
      if (!mean) continue;
      ++in_view;
      const int parity = Parity(static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
      if (std::abs(*mean - level[parity]) < std::abs(*mean - level[1 - parity])) ++matching;
      ring_sum[parity] += *mean;
      ++ring_count[parity];
    }
    if (in_view < kMinRingSquares) {
      *border = *border || found > 0;
      return found;
    }
    // The ring's squares must alternate with the board's phase, at least half as strongly.
    if (matching < kMatchingFraction * in_view || ring_count[0] == 0 || ring_count[1] == 0 ||
        !((ring_sum[0] / ring_count[0] - ring_sum[1] / ring_count[1]) / (level[0] - level[1]) >
          0.5)) {
      return found;
    }

    // The next corner line: predicted, then located on the image.
    std::vector<cv::Point2f> corners;
    std::vector<int> index;
    const double side = cv::norm(Apply(H, frontier + sign, 0.0) - Apply(H, frontier, 0.0));
    const int window = std::max(2, static_cast<int>(0.25 * side));
    for (int b = 0; b < across; ++b) {
      const double x = axis == 0 ? frontier + sign : b;
      const double y = axis == 0 ? b : frontier + sign;
      const cv::Point2d p = Apply(H, x, y);
      if (p.x < window + 1 || p.y < window + 1 || p.x > gray.cols - window - 2 ||
          p.y > gray.rows - window - 2) {
        continue;
      }
      corners.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
      index.push_back(b);
    }
    if (corners.size() < 2) {
      *border = true;
      return found + 1;
    }
    cv::cornerSubPix(gray, corners, cv::Size(window, window), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 20, 0.01));
    frontier += sign;
    ++found;
    for (std::size_t k = 0; k < corners.size(); ++k) grid[key(frontier, index[k])] = corners[k];
  }
  return found;
}

}  // namespace

ChessboardExtent MeasureChessboardExtent(const cv::Mat& gray, int cols, int rows,
                                         const std::vector<Eigen::Vector2d>& corners) {
  ChessboardExtent extent;
  if (cols < kFitLines || rows < kFitLines ||
      corners.size() != static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows)) {
    return extent;
  }
  Grid grid;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const Eigen::Vector2d& p = corners[static_cast<std::size_t>(r * cols + c)];
      grid[{c, r}] = cv::Point2d(p.x(), p.y());
    }
  }
  const Checker checker = MeasureChecker(gray, grid, cols, rows);
  extent.alternation = checker.fraction;
  extent.contrast = checker.contrast;
  if (checker.fraction < kMixedFraction || checker.contrast < kMixedContrast) {
    extent.not_neighbours = true;
    return extent;
  }
  if (!(checker.fraction >= kMatchingFraction && checker.contrast >= kCheckerContrast)) {
    return extent;
  }
  const double* level = checker.level;
  extent.before_x = Walk(gray, grid, cols, rows, 0, -1, level, &extent.out_of_view);
  extent.after_x = Walk(gray, grid, cols, rows, 0, +1, level, &extent.out_of_view);
  extent.before_y = Walk(gray, grid, cols, rows, 1, -1, level, &extent.out_of_view);
  extent.after_y = Walk(gray, grid, cols, rows, 1, +1, level, &extent.out_of_view);
  return extent;
}

}  // namespace hecal::vision
