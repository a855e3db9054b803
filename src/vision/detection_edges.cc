// Sub-pixel corners from straight edges (detection.h): marker corners (aruco_grid,
// apriltag_grid) and the saddle corners of chessboards and ChArUco boards.
//
// Why not cv::cornerSubPix: it places the corner where image gradients are orthogonal to p − q
// over a window, which is sensitive to the few pixels next to the corner. At a marker's L-corner
// (a black square's corner on white) blur rounds the corner and that condition is met inside the
// square: measured 0.15–0.25 px inwards at σ = 0.7 px. At saddle corners the pixel sampling of
// the gradient near the corner leaves 0.04–0.1 px (window 3–10 px). A straight step edge blurred
// by a symmetric point-spread function keeps its position, and far from the corners the edges are
// straight, so hecal locates edges and intersects them:
//
//   Edge samples. In a band of half-width w around a segment, every pixel's Sobel gradient
//   projected on the segment's normal, keeping pixels whose gradient points within 20° of the
//   normal. Near the segment's ends other edges cross it (the marker's adjacent sides, the other
//   grid line): the band is cut off where it comes within 15% (markers) / 20% (grids) of the
//   segment's length of those crossing lines — cut across the segment, so every sampled
//   cross-section of the edge stays whole even where the crossing edge meets it obliquely (a
//   cut parallel to the crossing edge biased tilted views by 0.05 px). The weighted centroid of
//   a blurred step's derivative is the edge, so a least-squares fit of the offset d(t) of the
//   samples (t along the segment, weights = the projections) traces the edge.
//   Markers: per side a line, only the dominant polarity of the projection (the marker's outer
//   edge; the border's inner edges and neighbouring markers have the opposite polarity within a
//   cell); w = 0.75 × the marker's cell; corners = intersections of adjacent sides. Markers whose
//   cells are under 2 px keep their corners. Lens distortion bends the sides, and a line fitted
//   to the middle 70% of a bent side and intersected with its neighbour misses the corner: with
//   k1 = −0.12 (f = 620 px) the corners of 150–200 px tags came out 0.1–0.3 px outward, a scale
//   of the pose (docs/targets.md). So when the camera is known the sides are fitted where they
//   are straight: each sample's pixel centre is mapped to ideal pixels (the pinhole image with
//   the same fx, fy, cx, cy and no distortion: K·pose::Undistort), the line is fitted to the
//   samples' offsets there (band, crossings and weights stay those of the image), the corners
//   are intersected there and projected back through the distortion (pose::Project). A blurred
//   edge's cross-section is a few pixels wide, over which the distortion map is affine to
//   < 1e-4 px, so the weighted centroid still maps to the edge. Where the camera model cannot be
//   undistorted (beyond the fold of a strong barrel model, pose/camera_model.h) the samples are
//   left out, and a marker whose corners are there is refined in pixels, as without the camera.
//   Saddle corners (grids of inner corners, neighbours one square apart): through each corner
//   the two grid lines, each from the segments to the two neighbours along that line (the outer
//   squares beyond the first and last corners are printed, so a missing neighbour is
//   extrapolated, p − (q − p)); |projection| weights (one edge per band); a quadratic
//   d(t) = a + b t + c t² across both segments absorbs lens distortion's curvature; the corner is
//   the intersection of the two curves (Newton). w = the caller's band fraction × the distance
//   to the nearest neighbour (narrow bands were more accurate in every test: they keep out the
//   tails of other edges). A corner without neighbours along both lines keeps its position.
//   Both: repeated until the corners move less than 1e-3 px (at most 10 times); an update larger
//   than a cell / quarter square is rejected and the previous corners are kept.
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "detection_internal.h"
#include "hecal/pose/camera_model.h"

namespace hecal::vision::internal {
namespace {

constexpr double kMarkerBand = 0.75;       // of a marker cell
constexpr double kMarkerSideStart = 0.15;  // of the side, from the adjacent sides
constexpr double kGridSegmentStart = 0.2;  // of a segment, from the crossing lines
constexpr double kMinCellPixels = 2.0;
constexpr double kMinAlignment = 0.94;  // cos 20°: gradient direction within 20° of the normal
constexpr int kMaxIterations = 10;
constexpr double kConvergence = 1e-3;  // px

struct EdgeSample {
  double t = 0.0;           // along the segment, from the origin, px
  double d = 0.0;           // along the normal, px
  double projection = 0.0;  // gradient · normal, grey levels / px
};

// A line through `point` along the unit `direction`; samples closer than min_distance to it are
// skipped (another edge meets the fitted one there).
struct Crossing {
  Eigen::Vector2d point;
  Eigen::Vector2d direction;
  double min_distance = 0.0;
};

class Gradients {
 public:
  explicit Gradients(const cv::Mat& gray) {
    // Sobel 3×3 scaled by 1/8: the central difference of the [1 2 1]/4-smoothed image.
    cv::Sobel(gray, gx_, CV_32F, 1, 0, 3, 1.0 / 8.0);
    cv::Sobel(gray, gy_, CV_32F, 0, 1, 3, 1.0 / 8.0);
  }

  // Samples of the pixels whose centre p has t = (p − origin)·along in [t_min, t_max] and
  // |d| = |(p − origin)·normal| ≤ half_width, leaving out every t where the band comes within a
  // crossing's min_distance of that crossing line (the edges that meet this one). Cutting by t
  // only keeps every sampled cross-section of the edge whole, so its centroid stays on the edge
  // also where the crossing edges meet it obliquely. Appended to *samples.
  void Band(const Eigen::Vector2d& origin, const Eigen::Vector2d& along,
            const Eigen::Vector2d& normal, double t_min, double t_max, double half_width,
            const std::vector<Crossing>& crossings, std::vector<EdgeSample>* samples) const {
    std::vector<std::pair<double, double>> excluded;
    for (const Crossing& c : crossings) {
      const double sine = std::abs(along.x() * c.direction.y() - along.y() * c.direction.x());
      if (!(sine > 1e-6)) return;  // parallel: no usable section
      const Eigen::Vector2d crossing_normal(-c.direction.y(), c.direction.x());
      // Where the crossing line meets this one, and how far along it the strip reaches.
      const double t_cross = (c.point - origin).dot(crossing_normal) / along.dot(crossing_normal);
      const double cosine = std::abs(along.dot(c.direction));
      const double reach = (c.min_distance + half_width * cosine) / sine;
      excluded.emplace_back(t_cross - reach, t_cross + reach);
    }
    const Eigen::Vector2d p0 = origin + t_min * along, p1 = origin + t_max * along;
    const int u0 = std::max(0, static_cast<int>(std::floor(std::min(p0.x(), p1.x()) - half_width)));
    const int u1 =
        std::min(gx_.cols - 1, static_cast<int>(std::ceil(std::max(p0.x(), p1.x()) + half_width)));
    const int v0 = std::max(0, static_cast<int>(std::floor(std::min(p0.y(), p1.y()) - half_width)));
    const int v1 =
        std::min(gx_.rows - 1, static_cast<int>(std::ceil(std::max(p0.y(), p1.y()) + half_width)));
    for (int v = v0; v <= v1; ++v) {
      for (int u = u0; u <= u1; ++u) {
        const Eigen::Vector2d offset = Eigen::Vector2d(u, v) - origin;
        const double t = offset.dot(along);
        const double d = offset.dot(normal);
        if (t < t_min || t > t_max || std::abs(d) > half_width) continue;
        const bool near_crossing = std::any_of(
            excluded.begin(), excluded.end(),
            [t](const std::pair<double, double>& e) { return t > e.first && t < e.second; });
        if (near_crossing) continue;
        const Eigen::Vector2d g(gx_.at<float>(v, u), gy_.at<float>(v, u));
        const double projection = g.dot(normal);
        // Gradients far from the normal belong to other edges (those crossing this one).
        if (std::abs(projection) < kMinAlignment * g.norm()) continue;
        samples->push_back({t, d, projection});
      }
    }
  }

 private:
  cv::Mat gx_, gy_;
};

// Weighted least-squares fit of d(t) = Σ_k c_k t^k, k < N (N = 2: a line, 3: a quadratic);
// nullopt when the weights do not determine it. Unused coefficients are 0.
template <int N>
std::optional<Eigen::Vector3d> FitCurve(const std::vector<EdgeSample>& samples,
                                        const std::vector<double>& weights) {
  Eigen::Matrix<double, N, N> normal = Eigen::Matrix<double, N, N>::Zero();
  Eigen::Matrix<double, N, 1> rhs = Eigen::Matrix<double, N, 1>::Zero();
  for (size_t k = 0; k < samples.size(); ++k) {
    if (!(weights[k] > 0.0)) continue;
    Eigen::Matrix<double, N, 1> basis;
    double power = 1.0;
    for (int i = 0; i < N; ++i, power *= samples[k].t) basis(i) = power;
    normal += weights[k] * basis * basis.transpose();
    rhs += weights[k] * samples[k].d * basis;
  }
  const Eigen::LDLT<Eigen::Matrix<double, N, N>> ldlt(normal);
  if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-12)) return std::nullopt;
  Eigen::Vector3d coefficients = Eigen::Vector3d::Zero();
  coefficients.template head<N>() = ldlt.solve(rhs);
  if (!coefficients.allFinite()) return std::nullopt;
  return coefficients;
}

// An edge curve: origin + t·along + d(t)·normal, d(t) = c0 + c1 t + c2 t².
struct Curve {
  Eigen::Vector2d origin, along, normal;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();

  Eigen::Vector2d At(double t) const {
    return origin + t * along + (c(0) + t * (c(1) + t * c(2))) * normal;
  }
  Eigen::Vector2d Slope(double t) const { return along + (c(1) + 2.0 * t * c(2)) * normal; }
};

// The intersection of two curves by Newton's method from t = 0 on both.
std::optional<Eigen::Vector2d> Intersect(const Curve& first, const Curve& second) {
  Eigen::Vector2d t = Eigen::Vector2d::Zero();
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Eigen::Vector2d residual = first.At(t(0)) - second.At(t(1));
    Eigen::Matrix2d J;
    J << first.Slope(t(0)), -second.Slope(t(1));
    if (!(std::abs(J.determinant()) > 1e-9)) return std::nullopt;
    const Eigen::Vector2d step = J.colPivHouseholderQr().solve(residual);
    t -= step;
    if (step.norm() < 1e-9) break;
  }
  const Eigen::Vector2d point = first.At(t(0));
  if (!point.allFinite()) return std::nullopt;
  return point;
}

using Quad = std::array<Eigen::Vector2d, 4>;

// Pixels ↔ ideal pixels, where the pinhole camera with the same fx, fy, cx, cy and no distortion
// sees the same ray (K·pose::Undistort one way, pose::Project the other): the marker's sides are
// straight there. The identity without a camera or distortion.
class Lens {
 public:
  explicit Lens(const std::optional<pose::CameraModel>& camera) {
    if (camera && camera->HasDistortion()) camera_ = camera;
  }

  std::optional<Eigen::Vector2d> Ideal(const Eigen::Vector2d& pixel) const {
    if (!camera_) return pixel;
    const std::optional<Eigen::Vector2d> normalised = pose::Undistort(*camera_, pixel);
    if (!normalised) return std::nullopt;
    return Eigen::Vector2d(camera_->fx * normalised->x() + camera_->cx,
                           camera_->fy * normalised->y() + camera_->cy);
  }
  Eigen::Vector2d Pixel(const Eigen::Vector2d& ideal) const {
    if (!camera_) return ideal;
    return pose::Project(*camera_, Eigen::Vector3d((ideal.x() - camera_->cx) / camera_->fx,
                                                   (ideal.y() - camera_->cy) / camera_->fy, 1.0));
  }
  bool identity() const { return !camera_; }

 private:
  std::optional<pose::CameraModel> camera_;
};

// The frame of side k of quad q (corners in order around it): origin at corner k, `along`
// towards corner k + 1, `normal` out of the quad.
Curve SideFrame(const Quad& q, int k) {
  const Eigen::Vector2d& a = q[k];
  const Eigen::Vector2d& b = q[(k + 1) % 4];
  const Eigen::Vector2d centre = (q[0] + q[1] + q[2] + q[3]) / 4.0;
  Curve side;
  side.origin = a;
  side.along = (b - a).normalized();
  side.normal = Eigen::Vector2d(side.along.y(), -side.along.x());
  if (side.normal.dot(0.5 * (a + b) - centre) < 0.0) side.normal = -side.normal;
  return side;
}

// Marker side k as a line in ideal pixels (see the header comment): sampled around the side of
// quad q (pixels), fitted in the frame of the same side of `ideal` (q in ideal pixels).
std::optional<Curve> MarkerSide(const Gradients& gradients, const Lens& lens, const Quad& q,
                                const Quad& ideal, int k, double half_width) {
  const Curve image_side = SideFrame(q, k);
  const Eigen::Vector2d& a = q[k];
  const Eigen::Vector2d& b = q[(k + 1) % 4];
  const double length = (b - a).norm();
  const std::vector<Crossing> crossings = {
      {a, (a - q[(k + 3) % 4]).normalized(), kMarkerSideStart * length},
      {b, (q[(k + 2) % 4] - b).normalized(), kMarkerSideStart * length}};
  std::vector<EdgeSample> samples;
  gradients.Band(a, image_side.along, image_side.normal, 0.0, length, half_width, crossings,
                 &samples);
  double positive = 0.0, negative = 0.0;
  for (const EdgeSample& s : samples)
    (s.projection > 0.0 ? positive : negative) += std::abs(s.projection);
  const double sign = positive >= negative ? 1.0 : -1.0;
  std::vector<double> weights;
  for (const EdgeSample& s : samples) weights.push_back(std::max(0.0, sign * s.projection));
  Curve side = SideFrame(ideal, k);
  if (!lens.identity()) {
    for (size_t i = 0; i < samples.size(); ++i) {
      if (!(weights[i] > 0.0)) continue;
      const std::optional<Eigen::Vector2d> p =
          lens.Ideal(a + samples[i].t * image_side.along + samples[i].d * image_side.normal);
      if (!p) {
        weights[i] = 0.0;
        continue;
      }
      samples[i].t = (*p - side.origin).dot(side.along);
      samples[i].d = (*p - side.origin).dot(side.normal);
    }
  }
  const std::optional<Eigen::Vector3d> c = FitCurve<2>(samples, weights);
  if (!c) return std::nullopt;
  side.c = *c;
  return side;
}

void RefineQuad(const Gradients& gradients, const Lens& lens, int cells_across,
                std::vector<cv::Point2f>* quad) {
  Quad q;
  for (int k = 0; k < 4; ++k) q[k] = Eigen::Vector2d((*quad)[k].x, (*quad)[k].y);
  double perimeter = 0.0;
  for (int k = 0; k < 4; ++k) perimeter += (q[(k + 1) % 4] - q[k]).norm();
  const double cell = perimeter / 4.0 / cells_across;
  if (cell < kMinCellPixels) return;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    Quad ideal;
    for (int k = 0; k < 4; ++k) {
      const std::optional<Eigen::Vector2d> corner = lens.Ideal(q[k]);
      if (!corner) return;
      ideal[k] = *corner;
    }
    std::array<Curve, 4> sides;
    for (int k = 0; k < 4; ++k) {
      const std::optional<Curve> side =
          MarkerSide(gradients, lens, q, ideal, k, kMarkerBand * cell);
      if (!side) return;
      sides[k] = *side;
    }
    Quad next;
    double shift = 0.0;
    for (int k = 0; k < 4; ++k) {
      const std::optional<Eigen::Vector2d> corner = Intersect(sides[(k + 3) % 4], sides[k]);
      if (!corner) return;
      next[k] = lens.Pixel(*corner);
      shift = std::max(shift, (next[k] - q[k]).norm());
    }
    if (shift > cell) return;  // the fit left the marker: keep the corners we had
    q = next;
    for (int k = 0; k < 4; ++k) {
      (*quad)[k] = cv::Point2f(static_cast<float>(q[k].x()), static_cast<float>(q[k].y()));
    }
    if (shift < kConvergence) return;
  }
}

// The grid line through corner p towards neighbours `before` and `after` (either may be
// missing, not both), as a quadratic curve in p's frame; `crossing` is the direction of the other
// grid line through p (the grid lines through the neighbours are taken parallel to it).
std::optional<Curve> GridLine(const Gradients& gradients, const Eigen::Vector2d& p,
                              std::optional<Eigen::Vector2d> before,
                              std::optional<Eigen::Vector2d> after, const Eigen::Vector2d& crossing,
                              double half_width) {
  if (!before && !after) return std::nullopt;
  if (!before) before = p - (*after - p);
  if (!after) after = p - (*before - p);
  Curve line;
  line.origin = p;
  line.along = (*after - *before).normalized();
  line.normal = Eigen::Vector2d(-line.along.y(), line.along.x());
  const double length_before = (p - *before).norm(), length_after = (*after - p).norm();
  std::vector<EdgeSample> samples;
  gradients.Band(p, line.along, line.normal, -length_before, 0.0, half_width,
                 {{p, crossing, kGridSegmentStart * length_before},
                  {*before, crossing, kGridSegmentStart * length_before}},
                 &samples);
  gradients.Band(p, line.along, line.normal, 0.0, length_after, half_width,
                 {{p, crossing, kGridSegmentStart * length_after},
                  {*after, crossing, kGridSegmentStart * length_after}},
                 &samples);
  std::vector<double> weights;
  for (const EdgeSample& s : samples) weights.push_back(std::abs(s.projection));
  const std::optional<Eigen::Vector3d> c = FitCurve<3>(samples, weights);
  if (!c) return std::nullopt;
  line.c = *c;
  return line;
}

// The unit direction of the grid line through p from its neighbours (nullopt without any).
std::optional<Eigen::Vector2d> Direction(const Eigen::Vector2d& p,
                                         const std::optional<Eigen::Vector2d>& before,
                                         const std::optional<Eigen::Vector2d>& after) {
  if (before && after) return (*after - *before).normalized();
  if (after) return (*after - p).normalized();
  if (before) return (p - *before).normalized();
  return std::nullopt;
}

}  // namespace

void RefineMarkerCorners(const cv::Mat& gray, int cells_across,
                         const std::optional<pose::CameraModel>& camera,
                         std::vector<std::vector<cv::Point2f>>* markers) {
  const Gradients gradients(gray);
  const Lens lens(camera), pixels(std::nullopt);
  for (std::vector<cv::Point2f>& quad : *markers) {
    const bool undistorted = std::all_of(quad.begin(), quad.end(), [&lens](const cv::Point2f& p) {
      return lens.Ideal(Eigen::Vector2d(p.x, p.y)).has_value();
    });
    RefineQuad(gradients, undistorted ? lens : pixels, cells_across, &quad);
  }
}

void RefineSaddleCorners(const cv::Mat& gray, int cols, int rows, double band_fraction,
                         std::vector<std::optional<cv::Point2f>>* grid) {
  const Gradients gradients(gray);
  const auto at = [&](int c, int r) -> std::optional<Eigen::Vector2d> {
    if (c < 0 || r < 0 || c >= cols || r >= rows) return std::nullopt;
    const std::optional<cv::Point2f>& p = (*grid)[static_cast<size_t>(r * cols + c)];
    if (!p) return std::nullopt;
    return Eigen::Vector2d(p->x, p->y);
  };
  // Neighbours come from the input, so every corner is refined from the same data.
  std::vector<std::optional<cv::Point2f>> refined = *grid;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      std::optional<Eigen::Vector2d> p = at(c, r);
      if (!p) continue;
      double spacing = std::numeric_limits<double>::infinity();
      for (const auto& q : {at(c - 1, r), at(c + 1, r), at(c, r - 1), at(c, r + 1)}) {
        if (q) spacing = std::min(spacing, (*q - *p).norm());
      }
      const std::optional<Eigen::Vector2d> row_direction =
          Direction(*p, at(c - 1, r), at(c + 1, r));
      const std::optional<Eigen::Vector2d> column_direction =
          Direction(*p, at(c, r - 1), at(c, r + 1));
      if (!row_direction || !column_direction) continue;
      const double half_width = band_fraction * spacing;
      for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        const std::optional<Curve> along_row =
            GridLine(gradients, *p, at(c - 1, r), at(c + 1, r), *column_direction, half_width);
        const std::optional<Curve> along_column =
            GridLine(gradients, *p, at(c, r - 1), at(c, r + 1), *row_direction, half_width);
        if (!along_row || !along_column) break;
        const std::optional<Eigen::Vector2d> next = Intersect(*along_row, *along_column);
        if (!next || (*next - *p).norm() > 0.25 * spacing) break;
        const double shift = (*next - *p).norm();
        p = next;
        refined[static_cast<size_t>(r * cols + c)] =
            cv::Point2f(static_cast<float>(p->x()), static_cast<float>(p->y()));
        if (shift < kConvergence) break;
      }
    }
  }
  *grid = std::move(refined);
}

}  // namespace hecal::vision::internal
