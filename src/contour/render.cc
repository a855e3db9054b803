// Synthetic images of a planar contour target: see render.h.
#include "hecal/contour/render.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "hecal/contour/perspective_view.h"
#include "hecal/core/error.h"
#include "hecal/core/options_check.h"
#include "hecal/core/random_draws.h"
#include "hecal/core/split_mix.h"

namespace hecal::contour {
namespace {

void CheckPolygon(const Eigen::Matrix2Xd& polygon, int width, int height, int supersampling) {
  if (width < 0 || height < 0) throw std::invalid_argument("render: negative image size");
  if (polygon.cols() < 3) throw std::invalid_argument("render: a polygon needs 3 vertices");
  if (!polygon.allFinite()) throw std::invalid_argument("render: a vertex is not finite");
  if (supersampling < 1) throw std::invalid_argument("render: supersampling must be ≥ 1");
}

// Adds `weight` × the overlap of [a, b] with every pixel column [x − ½, x + ½] of `row`.
void AddInterval(double a, double b, double weight, int width, double* row) {
  const double lo = std::max(a, -0.5);
  const double hi = std::min(b, width - 0.5);
  if (!(hi > lo)) return;
  const int first = static_cast<int>(std::floor(lo + 0.5));
  const int last = std::min(static_cast<int>(std::floor(hi + 0.5)), width - 1);
  for (int x = first; x <= last; ++x) {
    const double overlap = std::min(hi, x + 0.5) - std::max(lo, x - 0.5);
    if (overlap > 0.0) row[x] += weight * overlap;
  }
}

}  // namespace

GrayImage PolygonCoverage(const Eigen::Matrix2Xd& polygon, int width, int height,
                          int supersampling) {
  CheckPolygon(polygon, width, height, supersampling);
  GrayImage coverage(width, height, 0.0f);
  if (width == 0 || height == 0) return coverage;
  const Eigen::Index n = polygon.cols();
  const double y_min = polygon.row(1).minCoeff();
  const double y_max = polygon.row(1).maxCoeff();
  const int row_first = std::max(0, static_cast<int>(std::floor(y_min + 0.5)));
  const int row_last = std::min(height - 1, static_cast<int>(std::floor(y_max + 0.5)));
  const double weight = 1.0 / supersampling;
  std::vector<double> crossings;
  std::vector<double> row_sum(static_cast<std::size_t>(width));  // one row, in double
  for (int y = row_first; y <= row_last; ++y) {
    std::fill(row_sum.begin(), row_sum.end(), 0.0);
    for (int m = 0; m < supersampling; ++m) {
      const double scan_y = y - 0.5 + (m + 0.5) * weight;
      crossings.clear();
      for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Index j = i + 1 == n ? 0 : i + 1;
        const double y0 = polygon(1, i), y1 = polygon(1, j);
        if ((y0 <= scan_y) == (y1 <= scan_y)) continue;  // half-open: each crossing counted once
        const double x0 = polygon(0, i), x1 = polygon(0, j);
        crossings.push_back(x0 + (scan_y - y0) * (x1 - x0) / (y1 - y0));
      }
      std::sort(crossings.begin(), crossings.end());
      for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
        AddInterval(crossings[k], crossings[k + 1], weight, width, row_sum.data());
      }
    }
    for (int x = 0; x < width; ++x) {
      coverage.at(x, y) = static_cast<float>(std::min(1.0, row_sum[static_cast<std::size_t>(x)]));
    }
  }
  return coverage;
}

void GaussianBlur(GrayImage* image, double sigma) {
  if (!(sigma >= 0.0) || !std::isfinite(sigma)) {
    throw std::invalid_argument("render: the blur σ must be finite and ≥ 0");
  }
  if (sigma == 0.0 || image->empty()) return;
  const int radius = std::max(1, static_cast<int>(std::ceil(3.0 * sigma)));
  std::vector<double> taps(static_cast<std::size_t>(2 * radius + 1));
  double sum = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    const double w = std::exp(-0.5 * i * i / (sigma * sigma));
    taps[static_cast<std::size_t>(i + radius)] = w;
    sum += w;
  }
  for (double& w : taps) w /= sum;
  const int width = image->width(), height = image->height();
  GrayImage rows(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      double value = 0.0;
      for (int i = -radius; i <= radius; ++i) {
        value += taps[static_cast<std::size_t>(i + radius)] *
                 image->at(std::clamp(x + i, 0, width - 1), y);
      }
      rows.at(x, y) = static_cast<float>(value);
    }
  }
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      double value = 0.0;
      for (int i = -radius; i <= radius; ++i) {
        value += taps[static_cast<std::size_t>(i + radius)] *
                 rows.at(x, std::clamp(y + i, 0, height - 1));
      }
      image->at(x, y) = static_cast<float>(value);
    }
  }
}

void AddGaussianNoise(GrayImage* image, double sigma, std::uint64_t seed) {
  if (!(sigma >= 0.0) || !std::isfinite(sigma)) {
    throw std::invalid_argument("render: the noise σ must be finite and ≥ 0");
  }
  if (sigma == 0.0) return;
  std::mt19937_64 engine(SplitMix64(seed));
  hecal::NormalDistribution normal(0.0, sigma);
  for (float& value : image->pixels()) value = static_cast<float>(value + normal(engine));
}

void QuantizeGrey(GrayImage* image) {
  for (float& value : image->pixels()) value = std::clamp(std::round(value), 0.0f, 255.0f);
}

bool RenderOptions::IsValid(std::string* why) const {
  if (!std::isfinite(foreground)) {
    return Invalid(why, "RenderOptions.foreground", "the grey level must be finite",
                   "give the grey level inside the contour (default 180)");
  }
  if (!std::isfinite(background)) {
    return Invalid(why, "RenderOptions.background", "the grey level must be finite",
                   "give the grey level outside the contour (default 60)");
  }
  if (supersampling < 1) {
    return Invalid(why, "RenderOptions.supersampling",
                   "must be at least 1, got " + std::to_string(supersampling), "use e.g. 16");
  }
  if (!(blur_sigma >= 0.0) || !std::isfinite(blur_sigma)) {
    return Invalid(why, "RenderOptions.blur_sigma", "the blur σ must be finite and ≥ 0",
                   "give σ in pixels, 0 for none");
  }
  if (!(noise_sigma >= 0.0) || !std::isfinite(noise_sigma)) {
    return Invalid(why, "RenderOptions.noise_sigma", "the noise σ must be finite and ≥ 0",
                   "give σ in grey levels, 0 for none");
  }
  return true;
}

GrayImage RenderPolygon(const Eigen::Matrix2Xd& polygon, int width, int height,
                        const RenderOptions& options) {
  RequireValid(options);
  GrayImage image = PolygonCoverage(polygon, width, height, options.supersampling);
  GaussianBlur(&image, options.blur_sigma);
  const double contrast = options.foreground - options.background;
  for (float& value : image.pixels()) {
    value = static_cast<float>(options.background + contrast * value);
  }
  AddGaussianNoise(&image, options.noise_sigma, options.seed);
  if (options.quantize) QuantizeGrey(&image);
  return image;
}

Eigen::Matrix2Xd PerspectiveOutline(const ClosedBSpline& target, const Eigen::Matrix3d& rotation,
                                    const Eigen::Vector3d& translation, const ContourCamera& camera,
                                    const Eigen::Vector2d& principal_point, int samples_per_span) {
  if (samples_per_span < 1) throw std::invalid_argument("render: samples_per_span must be ≥ 1");
  Eigen::Matrix2Xd outline =
      ProjectPerspective(target.Sample(samples_per_span), rotation, translation, camera);
  outline.colwise() += principal_point;
  return outline;
}

GrayImage RenderPlanarTarget(const ClosedBSpline& target, const Eigen::Matrix3d& rotation,
                             const Eigen::Vector3d& translation, const ContourCamera& camera,
                             const Eigen::Vector2d& principal_point, int width, int height,
                             const RenderOptions& options, int samples_per_span) {
  return RenderPolygon(
      PerspectiveOutline(target, rotation, translation, camera, principal_point, samples_per_span),
      width, height, options);
}

}  // namespace hecal::contour
