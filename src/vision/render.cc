// Inverse-mapping renderer of calibration targets (see render.h for the model and the pattern).
#include "hecal/vision/render.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/aruco/charuco.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <random>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "detection_internal.h"
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/core/pixel_jitter.h"
#include "hecal/core/random_draws.h"

namespace hecal::vision {
namespace {

constexpr double kOffBoard = std::numeric_limits<double>::quiet_NaN();

// Square markers laid out on a regular lattice: lattice cell (c, r) may hold a marker drawn as
// n × n cells of side `cell`, its top-left at origin + (c, r)·pitch; n·cell ≤ pitch, so a point
// can only lie on the marker of the lattice cell it falls in.
struct MarkerLattice {
  double origin_x = 0.0;
  double origin_y = 0.0;
  double pitch = 1.0;
  double cell = 1.0;
  int n = 0;
  int cols = 0;
  int rows = 0;
  std::vector<cv::Mat> cells;  // per lattice cell r·cols + c: n × n CV_8U, 1 = white; empty: none

  // The marker's reflectance at (x, y), or nullopt when (x, y) is on no marker.
  std::optional<double> At(double x, double y) const {
    const double u = (x - origin_x) / pitch;
    const double v = (y - origin_y) / pitch;
    const int c = static_cast<int>(std::floor(u));
    const int r = static_cast<int>(std::floor(v));
    if (c < 0 || r < 0 || c >= cols || r >= rows) return std::nullopt;
    const cv::Mat& marker = cells[static_cast<size_t>(r * cols + c)];
    if (marker.empty()) return std::nullopt;
    const int i = static_cast<int>(std::floor((u - c) * pitch / cell));
    const int j = static_cast<int>(std::floor((v - r) * pitch / cell));
    if (i < 0 || j < 0 || i >= n || j >= n) return std::nullopt;
    return marker.at<uchar>(j, i);
  }

  // Lattice cell of a marker whose drawn top-left corner is at (x, y).
  size_t IndexAt(double x, double y) const {
    const int c = static_cast<int>(std::lround((x - origin_x) / pitch));
    const int r = static_cast<int>(std::lround((y - origin_y) / pitch));
    return static_cast<size_t>(r * cols + c);
  }
};

// The number of outer rings of a marker's cells that are entirely white (they print like the
// paper around them).
int WhiteRings(const cv::Mat& cells) {
  int rings = 0;
  while (2 * (rings + 1) < cells.rows) {
    const int first = rings;
    const int last = cells.rows - 1 - rings;
    const cv::Range span(first, last + 1);
    const int white = cv::countNonZero(cells.row(first).colRange(span)) +
                      cv::countNonZero(cells.row(last).colRange(span)) +
                      cv::countNonZero(cells.col(first).rowRange(span)) +
                      cv::countNonZero(cells.col(last).rowRange(span));
    if (white != 4 * (last - first + 1)) break;
    ++rings;
  }
  return rings;
}

// Cells of an ArUco marker: a black border cell around the dictionary bits (1 = white).
cv::Mat ArucoCells(const cv::aruco::Dictionary& dictionary, int id) {
  const cv::Mat bits = cv::aruco::Dictionary::getBitsFromByteList(
      dictionary.bytesList.rowRange(id, id + 1), dictionary.markerSize);
  cv::Mat cells = cv::Mat::zeros(dictionary.markerSize + 2, dictionary.markerSize + 2, CV_8U);
  bits.copyTo(cells(cv::Rect(1, 1, dictionary.markerSize, dictionary.markerSize)));
  return cells;
}

// The markers of an OpenCV board (charuco or grid), on a lattice of the given origin and pitch.
MarkerLattice OpenCvBoardMarkers(const cv::aruco::Board& board, double origin_x, double origin_y,
                                 double pitch, double marker, int cols, int rows) {
  MarkerLattice lattice;
  lattice.origin_x = origin_x;
  lattice.origin_y = origin_y;
  lattice.pitch = pitch;
  lattice.n = board.dictionary->markerSize + 2;
  lattice.cell = marker / lattice.n;
  lattice.cols = cols;
  lattice.rows = rows;
  lattice.cells.resize(static_cast<size_t>(cols * rows));
  for (size_t k = 0; k < board.ids.size(); ++k) {
    const cv::Point3f& top_left = board.objPoints[k][0];
    lattice.cells[lattice.IndexAt(top_left.x, top_left.y)] =
        ArucoCells(*board.dictionary, board.ids[k]);
  }
  return lattice;
}

// The printed board: reflectance (0 black .. 1 white) at a point of the target plane, NaN off
// the board.
class PrintedBoard {
 public:
  PrintedBoard(const pose::TargetSpec& target, const RenderOptions& options) : target_(target) {
    double pitch = target.square;
    double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;  // the pattern's extent
    switch (target.type) {
      case pose::TargetType::kChessboard:
        x0 = -target.square;
        y0 = -target.square;
        x1 = target.cols * target.square;
        y1 = target.rows * target.square;
        break;
      case pose::TargetType::kCharuco: {
        const cv::Ptr<cv::aruco::CharucoBoard> board = cv::aruco::CharucoBoard::create(
            target.cols, target.rows, static_cast<float>(target.square),
            static_cast<float>(target.marker), internal::ArucoDictionary(target.dictionary));
        const double offset = (target.square - target.marker) / 2.0;
        markers_ = OpenCvBoardMarkers(*board, offset, offset, target.square, target.marker,
                                      target.cols, target.rows);
        x1 = target.cols * target.square;
        y1 = target.rows * target.square;
        break;
      }
      case pose::TargetType::kArucoGrid: {
        const cv::Ptr<cv::aruco::GridBoard> board = cv::aruco::GridBoard::create(
            target.cols, target.rows, static_cast<float>(target.marker),
            static_cast<float>(target.spacing), internal::ArucoDictionary(target.dictionary),
            target.first_id);
        markers_ = OpenCvBoardMarkers(*board, 0.0, 0.0, target.marker + target.spacing,
                                      target.marker, target.cols, target.rows);
        pitch = target.marker;
        x1 = target.cols * markers_.pitch - target.spacing;
        y1 = target.rows * markers_.pitch - target.spacing;
        break;
      }
      case pose::TargetType::kAruco: {
        const cv::Ptr<cv::aruco::Dictionary> dictionary =
            internal::ArucoDictionary(target.dictionary);
        markers_.n = dictionary->markerSize + 2;
        markers_.cell = target.size / markers_.n;
        markers_.pitch = target.size;
        markers_.cols = 1;
        markers_.rows = 1;
        markers_.origin_x = -target.size / 2.0;
        markers_.origin_y = -target.size / 2.0;
        markers_.cells = {ArucoCells(*dictionary, target.id)};
        pitch = target.size;
        x0 = y0 = -target.size / 2.0;
        x1 = y1 = target.size / 2.0;
        break;
      }
      case pose::TargetType::kAprilTagGrid:
      case pose::TargetType::kAprilTag: {
        const internal::MarkerGrid grid = internal::MarkerGridOf(target);
        SetAprilTags(target.family, grid);
        pitch = grid.marker;
        x0 = markers_.origin_x;
        y0 = markers_.origin_y;
        x1 = markers_.origin_x + (grid.cols - 1) * markers_.pitch + markers_.n * markers_.cell;
        y1 = markers_.origin_y + (grid.rows - 1) * markers_.pitch + markers_.n * markers_.cell;
        break;
      }
      case pose::TargetType::kCircles:
      case pose::TargetType::kAsymmetricCircles: {
        SetCircles(target, options.circle_radius);
        x0 = std::numeric_limits<double>::infinity();
        y0 = x0;
        x1 = -x0;
        y1 = -x0;
        for (const cv::Point2d& centre : centres_) {
          x0 = std::min(x0, centre.x - radius_);
          y0 = std::min(y0, centre.y - radius_);
          x1 = std::max(x1, centre.x + radius_);
          y1 = std::max(y1, centre.y + radius_);
        }
        break;
      }
    }
    const double border = options.margin * pitch;
    x0_ = x0 - border;
    y0_ = y0 - border;
    x1_ = x1 + border;
    y1_ = y1 + border;
  }

  double Reflectance(double x, double y) const {
    if (!(x >= x0_ && x <= x1_ && y >= y0_ && y <= y1_)) return kOffBoard;
    switch (target_.type) {
      case pose::TargetType::kChessboard: {
        const long i = static_cast<long>(std::floor(x / target_.square)) + 1;
        const long j = static_cast<long>(std::floor(y / target_.square)) + 1;
        if (i < 0 || j < 0 || i > target_.cols || j > target_.rows) return 1.0;
        return (i + j) % 2 == 0 ? 0.0 : 1.0;
      }
      case pose::TargetType::kCharuco: {
        if (const std::optional<double> value = markers_.At(x, y)) return *value;
        const long i = static_cast<long>(std::floor(x / target_.square));
        const long j = static_cast<long>(std::floor(y / target_.square));
        if (i < 0 || j < 0 || i >= target_.cols || j >= target_.rows) return 1.0;
        // Squares holding a marker are white, the others black (CharucoBoard's layout).
        return markers_.cells[static_cast<size_t>(j * target_.cols + i)].empty() ? 0.0 : 1.0;
      }
      case pose::TargetType::kArucoGrid:
      case pose::TargetType::kAprilTagGrid:
      case pose::TargetType::kAruco:
      case pose::TargetType::kAprilTag:
        return markers_.At(x, y).value_or(1.0);
      case pose::TargetType::kCircles:
      case pose::TargetType::kAsymmetricCircles:
        return OnCircle(x, y) ? 0.0 : 1.0;
    }
    return kOffBoard;
  }

 private:
  // The tags of an apriltag_grid, or the one tag of an apriltag target (a 1 × 1 grid).
  void SetAprilTags(const std::string& family_name, const internal::MarkerGrid& grid) {
    const internal::AprilTagFamily family(family_name);
    const int total_width = family.total_width();
    const int width_at_border = family.width_at_border();
    markers_.cell = grid.marker / width_at_border;
    markers_.cols = grid.cols;
    markers_.rows = grid.rows;
    markers_.cells.resize(static_cast<size_t>(grid.cols * grid.rows));
    // Outer rings that are white on every tag print like the paper: drop them, so that only
    // cells with ink must fit between neighbouring markers.
    int rings = total_width;
    for (size_t m = 0; m < markers_.cells.size(); ++m) {
      markers_.cells[m] = internal::AprilTagCells(family, grid.first_id + static_cast<int>(m));
      rings = std::min(rings, WhiteRings(markers_.cells[m]));
    }
    const int n = total_width - 2 * rings;
    for (cv::Mat& cells : markers_.cells) cells = cells(cv::Rect(rings, rings, n, n)).clone();
    markers_.n = n;
    const double overhang = (markers_.n - width_at_border) / 2.0 * markers_.cell;
    markers_.origin_x = grid.origin.x - overhang;
    markers_.origin_y = grid.origin.y - overhang;
    const double printed = markers_.n * markers_.cell;
    const double pitch = grid.marker + grid.spacing;
    if (markers_.cells.size() > 1 && printed > pitch * (1.0 + 1e-12)) {
      std::ostringstream problem;
      problem << "the " << family_name << " tags print " << markers_.n << " cells across ("
              << printed << " m), more than the marker pitch " << pitch
              << " m: neighbouring tags would overlap";
      throw InputError(
          "target", 0, problem.str(),
          "increase spacing to at least " + std::to_string(printed - grid.marker) + " m");
    }
    // A single tag has no neighbour: its lattice cell is the printed tag.
    markers_.pitch = std::max(pitch, printed);
  }

  void SetCircles(const pose::TargetSpec& target, double radius_fraction) {
    for (const pose::ObjectPoint& point : pose::ObjectPoints(target)) {
      centres_.emplace_back(point.position.x(), point.position.y());
    }
    double spacing = std::numeric_limits<double>::infinity();
    for (size_t a = 0; a < centres_.size(); ++a) {
      for (size_t b = a + 1; b < centres_.size(); ++b) {
        spacing = std::min(spacing, cv::norm(centres_[a] - centres_[b]));
      }
    }
    radius_ = radius_fraction * spacing;
    // Buckets of side 2·radius: a disc reaching a point lies in its bucket or a neighbour.
    bucket_ = 2.0 * radius_;
    for (size_t k = 0; k < centres_.size(); ++k) {
      buckets_.emplace(
          BucketKey(std::floor(centres_[k].x / bucket_), std::floor(centres_[k].y / bucket_)), k);
    }
  }

  static long long BucketKey(double i, double j) {
    return static_cast<long long>(i) * 1000003LL + static_cast<long long>(j);
  }

  bool OnCircle(double x, double y) const {
    const double i = std::floor(x / bucket_);
    const double j = std::floor(y / bucket_);
    for (double di = -1.0; di <= 1.0; di += 1.0) {
      for (double dj = -1.0; dj <= 1.0; dj += 1.0) {
        const auto [first, last] = buckets_.equal_range(BucketKey(i + di, j + dj));
        for (auto it = first; it != last; ++it) {
          const cv::Point2d& c = centres_[it->second];
          if ((x - c.x) * (x - c.x) + (y - c.y) * (y - c.y) <= radius_ * radius_) return true;
        }
      }
    }
    return false;
  }

  pose::TargetSpec target_;
  double x0_ = 0.0, y0_ = 0.0, x1_ = 0.0, y1_ = 0.0;  // white area, target frame
  MarkerLattice markers_;
  std::vector<cv::Point2d> centres_;
  double radius_ = 0.0;
  double bucket_ = 1.0;
  std::unordered_multimap<long long, size_t> buckets_;
};

}  // namespace

bool RenderOptions::IsValid(std::string* why) const {
  if (width < 0 || height < 0) {
    return Invalid(why, "RenderOptions.size", "width and height must be 0 or more",
                   "give the image size in pixels, or 0 for the camera's");
  }
  if (!(blur_sigma >= 0.0) || !std::isfinite(blur_sigma)) {
    return Invalid(why, "RenderOptions.blur_sigma", "must be a finite number of pixels, 0 or more",
                   "give the blur σ, 0 for none");
  }
  if (!(noise_sigma >= 0.0) || !std::isfinite(noise_sigma)) {
    return Invalid(why, "RenderOptions.noise_sigma",
                   "must be a finite number of grey levels, 0 or more",
                   "give the noise σ, 0 for none");
  }
  const std::pair<const char*, double> levels[] = {{"RenderOptions.background", background},
                                                   {"RenderOptions.black", black},
                                                   {"RenderOptions.white", white}};
  for (const auto& [field, level] : levels) {
    if (!(level >= 0.0 && level <= 255.0)) {
      return Invalid(why, field, "must be a grey level 0 … 255", "give an 8-bit grey level");
    }
  }
  if (!(margin >= 0.0) || !std::isfinite(margin)) {
    return Invalid(why, "RenderOptions.margin", "must be a finite number of pitches, 0 or more",
                   "give the white border in pattern pitches (default 1)");
  }
  if (!(circle_radius > 0.0 && circle_radius < 0.5)) {
    return Invalid(why, "RenderOptions.circle_radius",
                   "must be between 0 and 0.5 of the smallest centre distance",
                   "give e.g. 0.3 (the default)");
  }
  if (supersampling < 1 || supersampling > 64) {
    return Invalid(why, "RenderOptions.supersampling",
                   "must be 1 … 64, got " + std::to_string(supersampling),
                   "give the samples per pixel along each axis (default 8)");
  }
  return true;
}

cv::Mat RenderTarget(const pose::TargetSpec& target, const pose::CameraModel& camera,
                     const Pose& T_camera_target, const RenderOptions& options) {
  RequireValid(options);
  internal::RequireUsableTarget(target);
  const int width = options.width > 0 ? options.width : camera.width;
  const int height = options.height > 0 ? options.height : camera.height;
  if (width <= 0 || height <= 0) {
    throw InputError("options", 0, "no image size",
                     "set width and height in the options or camera");
  }
  const Pose T_target_camera = T_camera_target.inverse();
  const Eigen::Vector3d eye = T_target_camera.translation();
  if (!(eye.z() < 0.0)) {
    std::ostringstream problem;
    problem << "the camera centre is at z = " << eye.z()
            << " m in the target frame: it would see the back of the board";
    throw InputError("T_camera_target", 0, problem.str(),
                     "put the camera on the printed side (z < 0 in the target frame)");
  }
  const Eigen::Matrix3d R = T_target_camera.linear();
  const PrintedBoard board(target, options);

  // Undistorted normalised coordinates at the pixel corners (u, v) = (i − ½, j − ½).
  const int corner_cols = width + 1;
  std::vector<Eigen::Vector2d> corners(static_cast<size_t>(corner_cols * (height + 1)));
  for (int j = 0; j <= height; ++j) {
    for (int i = 0; i <= width; ++i) {
      const std::optional<Eigen::Vector2d> p =
          pose::Undistort(camera, Eigen::Vector2d(i - 0.5, j - 0.5));
      corners[static_cast<size_t>(j * corner_cols + i)] =
          p.value_or(Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN()));
    }
  }

  // The board's reflectance where the ray through normalised point n meets it; kOffBoard where
  // it misses.
  const auto reflectance_at = [&](const Eigen::Vector2d& n) {
    const Eigen::Vector3d ray = R * Eigen::Vector3d(n.x(), n.y(), 1.0);
    if (!(ray.z() > 0.0)) return kOffBoard;
    const double lambda = -eye.z() / ray.z();
    return board.Reflectance(eye.x() + lambda * ray.x(), eye.y() + lambda * ray.y());
  };
  const double contrast = options.white - options.black;
  const auto grey = [&](double reflectance) {
    return std::isnan(reflectance) ? options.background : options.black + contrast * reflectance;
  };

  // Pixels whose four corners see different greys (or that touch such a pixel) are
  // supersampled; the others are uniform (see render.h).
  std::vector<double> corner_grey(corners.size());
  for (size_t k = 0; k < corners.size(); ++k) {
    corner_grey[k] = corners[k].allFinite() ? grey(reflectance_at(corners[k])) : -1.0;
  }
  cv::Mat mixed(height, width, CV_8U);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const double g = corner_grey[static_cast<size_t>(j * corner_cols + i)];
      mixed.at<uchar>(j, i) =
          g != corner_grey[static_cast<size_t>(j * corner_cols + i + 1)] ||
                  g != corner_grey[static_cast<size_t>((j + 1) * corner_cols + i)] ||
                  g != corner_grey[static_cast<size_t>((j + 1) * corner_cols + i + 1)]
              ? 1
              : 0;
    }
  }
  cv::dilate(mixed, mixed, cv::Mat::ones(3, 3, CV_8U));

  const int s = options.supersampling;
  cv::Mat image(height, width, CV_32F);
  cv::parallel_for_(cv::Range(0, height), [&](const cv::Range& range) {
    for (int j = range.start; j < range.end; ++j) {
      float* row = image.ptr<float>(j);
      for (int i = 0; i < width; ++i) {
        const size_t k00 = static_cast<size_t>(j * corner_cols + i);
        const Eigen::Vector2d& p00 = corners[k00];
        const Eigen::Vector2d& p10 = corners[k00 + 1];
        const Eigen::Vector2d& p01 = corners[k00 + static_cast<size_t>(corner_cols)];
        const Eigen::Vector2d& p11 = corners[k00 + static_cast<size_t>(corner_cols) + 1];
        if (!(p00.allFinite() && p10.allFinite() && p01.allFinite() && p11.allFinite())) {
          row[i] = static_cast<float>(options.background);
          continue;
        }
        if (mixed.at<uchar>(j, i) == 0) {
          row[i] = static_cast<float>(corner_grey[k00]);
          continue;
        }
        const std::uint64_t pixel_key = PixelKey(i, j);
        double sum = 0.0;
        for (int b = 0; b < s; ++b) {
          for (int a = 0; a < s; ++a) {
            const auto [fx, fy] = JitteredSample(pixel_key, a, b, s);
            sum += grey(reflectance_at((1.0 - fy) * ((1.0 - fx) * p00 + fx * p10) +
                                       fy * ((1.0 - fx) * p01 + fx * p11)));
          }
        }
        row[i] = static_cast<float>(sum / (s * s));
      }
    }
  });

  if (options.blur_sigma > 0.0) {
    cv::GaussianBlur(image, image, cv::Size(0, 0), options.blur_sigma, options.blur_sigma,
                     cv::BORDER_REPLICATE);
  }
  if (options.noise_sigma > 0.0) {
    std::mt19937_64 generator(options.seed);
    hecal::NormalDistribution noise(0.0, options.noise_sigma);
    for (int j = 0; j < height; ++j) {
      float* row = image.ptr<float>(j);
      for (int i = 0; i < width; ++i) row[i] += static_cast<float>(noise(generator));
    }
  }
  cv::Mat out;
  image.convertTo(out, CV_8U);  // rounds to nearest and saturates
  return out;
}

}  // namespace hecal::vision
