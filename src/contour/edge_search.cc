// One-dimensional edge search along a curve normal: see edge_search.h.
#include "hecal/contour/edge_search.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "hecal/core/error.h"
#include "hecal/core/options_check.h"

namespace hecal::contour {

bool EdgeSearchOptions::IsValid(std::string* why) const {
  if (!(range > 0.0) || !std::isfinite(range)) {
    return Invalid(why, "EdgeSearchOptions.range", "must be positive and finite",
                   "use e.g. 10 px either side of the curve");
  }
  if (!(step > 0.0) || !(step <= range)) {
    return Invalid(why, "EdgeSearchOptions.step", "must be above 0 and at most the range",
                   "use e.g. 0.5 px");
  }
  if (!(derivative_sigma > 0.0) || !std::isfinite(derivative_sigma)) {
    return Invalid(why, "EdgeSearchOptions.derivative_sigma", "must be positive and finite",
                   "use e.g. 1 px");
  }
  if (!(min_gradient >= 0.0) || !std::isfinite(min_gradient)) {
    return Invalid(why, "EdgeSearchOptions.min_gradient", "must be non-negative and finite",
                   "use e.g. 10 grey levels per px");
  }
  if (polarity < -1 || polarity > 1) {
    return Invalid(why, "EdgeSearchOptions.polarity",
                   "must be -1, 0 or 1, got " + std::to_string(polarity),
                   "use +1 or -1 for one edge direction, 0 for either");
  }
  return true;
}

std::optional<EdgeHit> SearchEdge(const GrayImage& image, const Eigen::Vector2d& point,
                                  const Eigen::Vector2d& normal, const EdgeSearchOptions& options) {
  RequireValid(options);
  const double length = normal.norm();
  if (!std::isfinite(length) || !(length > 0.0)) {
    throw std::invalid_argument("SearchEdge: the normal must be a finite non-zero vector");
  }
  if (!point.allFinite()) return std::nullopt;
  const Eigen::Vector2d n = normal / length;
  const double step = options.step;
  const int half = static_cast<int>(std::floor(options.range / step + 1e-9));
  // Derivative-of-Gaussian taps w_m at m·step, |m·step| ≤ 3σ, scaled so that Σ w_m (m·step) = 1
  // (a unit ramp has derivative 1).
  const double sigma = options.derivative_sigma;
  const int d = std::max(1, static_cast<int>(std::ceil(3.0 * sigma / step)));
  std::vector<double> taps(static_cast<std::size_t>(2 * d + 1));
  double ramp = 0.0;
  for (int m = -d; m <= d; ++m) {
    const double t = m * step;
    const double w = t * std::exp(-0.5 * t * t / (sigma * sigma));
    taps[static_cast<std::size_t>(m + d)] = w;
    ramp += w * t;
  }
  for (double& w : taps) w /= ramp;

  // Profile p at k = −half − d … half + d (index k + half + d).
  const int total = 2 * (half + d) + 1;
  const Eigen::Vector2d first = point - (half + d) * step * n;
  const Eigen::Vector2d last = point + (half + d) * step * n;
  if (!image.Contains(first.x(), first.y()) || !image.Contains(last.x(), last.y())) {
    return std::nullopt;  // the segment is convex: both ends inside ⇒ all of it inside
  }
  std::vector<double> profile(static_cast<std::size_t>(total));
  for (int i = 0; i < total; ++i) {
    const Eigen::Vector2d p = first + i * step * n;
    profile[static_cast<std::size_t>(i)] = image.Sample(p.x(), p.y());
  }
  // g at k = −half … half (index k + half), and the value the peak search maximises.
  const int count = 2 * half + 1;
  std::vector<double> g(static_cast<std::size_t>(count));
  std::vector<double> score(static_cast<std::size_t>(count));
  int best = 0;
  for (int i = 0; i < count; ++i) {
    double value = 0.0;
    for (int m = 0; m <= 2 * d; ++m) {
      value += taps[static_cast<std::size_t>(m)] * profile[static_cast<std::size_t>(i + m)];
    }
    g[static_cast<std::size_t>(i)] = value;
    score[static_cast<std::size_t>(i)] =
        options.polarity == 0 ? std::abs(value) : options.polarity * value;
    if (score[static_cast<std::size_t>(i)] > score[static_cast<std::size_t>(best)]) best = i;
  }
  if (best == 0 || best == count - 1) return std::nullopt;
  const double peak = score[static_cast<std::size_t>(best)];
  if (!(peak >= options.min_gradient) || !(peak > 0.0)) return std::nullopt;
  const double before = score[static_cast<std::size_t>(best - 1)];
  const double after = score[static_cast<std::size_t>(best + 1)];
  const double curvature = before - 2.0 * peak + after;
  double shift = 0.0;
  if (curvature < 0.0) shift = 0.5 * (before - after) / curvature;
  shift = std::clamp(shift, -0.5, 0.5);
  EdgeHit hit;
  hit.offset = (best - half + shift) * step;
  hit.gradient = g[static_cast<std::size_t>(best)];
  return hit;
}

}  // namespace hecal::contour
