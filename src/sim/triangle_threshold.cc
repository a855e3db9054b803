#include "hecal/sim/triangle_threshold.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "hecal/core/options_check.h"

namespace hecal::sim {

std::vector<double> MovingAverage(std::span<const double> histogram, int window) {
  const int n = static_cast<int>(histogram.size());
  const int half = std::max(window, 1) / 2;
  std::vector<double> smoothed(histogram.size(), 0.0);
  for (int k = 0; k < n; ++k) {
    const int first = std::max(0, k - half);
    const int last = std::min(n - 1, k + half);
    double sum = 0.0;
    for (int j = first; j <= last; ++j) sum += histogram[j];
    smoothed[k] = sum / (last - first + 1);
  }
  return smoothed;
}

std::optional<int> TriangleThresholdBin(std::span<const double> histogram) {
  if (histogram.empty()) return std::nullopt;
  const int end = static_cast<int>(histogram.size()) - 1;  // the farthest bin
  const int peak =
      static_cast<int>(std::max_element(histogram.begin(), histogram.end()) - histogram.begin());
  const double peak_height = histogram[peak];
  const double end_height = histogram[end];
  // The perpendicular distance to a fixed line is the vertical gap times a constant, so the
  // vertical gap below the line ranks the bins.
  std::optional<int> best;
  double best_gap = 0.0;
  for (int k = peak + 1; k < end; ++k) {
    const double s = static_cast<double>(k - peak) / (end - peak);
    const double line = peak_height + s * (end_height - peak_height);
    const double gap = line - histogram[k];
    if (gap > best_gap) {
      best_gap = gap;
      best = k;
    }
  }
  return best;
}

bool TriangleThresholdOptions::IsValid(std::string* why) const {
  if (min_bins < 1) {
    return Invalid(why, "TriangleThresholdOptions.min_bins",
                   "must be at least 1, got " + std::to_string(min_bins), "use e.g. 5");
  }
  if (max_bins < min_bins) {
    return Invalid(why, "TriangleThresholdOptions.max_bins",
                   "must be at least min_bins (" + std::to_string(min_bins) + "), got " +
                       std::to_string(max_bins),
                   "use e.g. 15");
  }
  if (padding_bins < 0) {
    return Invalid(why, "TriangleThresholdOptions.padding_bins",
                   "must be 0 or more, got " + std::to_string(padding_bins), "use e.g. 2");
  }
  if (smoothing_window < 1 || smoothing_window % 2 == 0) {
    return Invalid(why, "TriangleThresholdOptions.smoothing_window",
                   "must be odd and at least 1, got " + std::to_string(smoothing_window),
                   "use e.g. 3 (1 for no smoothing)");
  }
  if (!std::isfinite(floor)) {
    return Invalid(why, "TriangleThresholdOptions.floor", "must be finite",
                   "give the smallest value worth binning, 0 for none");
  }
  if (!(knee_fraction > 0.0 && knee_fraction <= 1.0)) {
    return Invalid(why, "TriangleThresholdOptions.knee_fraction", "must be above 0 and at most 1",
                   "use e.g. 0.1");
  }
  return true;
}

TriangleThresholdResult TriangleThreshold(std::span<const double> values,
                                          const TriangleThresholdOptions& options) {
  RequireValid(options);
  TriangleThresholdResult result;
  result.threshold = std::numeric_limits<double>::infinity();
  result.outlier = std::vector<bool>(values.size(), false);

  double smallest_positive = std::numeric_limits<double>::infinity();
  int finite = 0;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    ++finite;
    if (v > 0.0) smallest_positive = std::min(smallest_positive, v);
  }
  if (finite < 3) return result;
  // Values below the floor are binned at the floor (log scale: also every value ≤ 0).
  const double floor =
      options.log_scale ? std::max(options.floor, smallest_positive) : options.floor;
  if (options.log_scale && !std::isfinite(floor)) return result;  // all ≤ 0

  auto scaled = [&](double v) {
    const double clamped = std::max(v, floor);
    return options.log_scale ? std::log10(clamped) : clamped;
  };
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, scaled(v));
    hi = std::max(hi, scaled(v));
  }
  if (!(hi > lo)) return result;

  const int bins = std::clamp(static_cast<int>(std::ceil(std::sqrt(static_cast<double>(finite)))),
                              options.min_bins, options.max_bins);
  const double width = (hi - lo) / bins;
  auto bin_of = [&](double v) {
    return std::clamp(static_cast<int>((scaled(v) - lo) / width), 0, bins - 1);
  };
  std::vector<double> histogram(bins + options.padding_bins, 0.0);
  for (double v : values) {
    if (std::isfinite(v)) histogram[bin_of(v)] += 1.0;
  }
  const std::vector<double> smoothed = MovingAverage(histogram, options.smoothing_window);
  const std::optional<int> threshold_bin = TriangleThresholdBin(smoothed);
  if (!threshold_bin || *threshold_bin >= bins - 1) return result;
  const double peak = *std::max_element(smoothed.begin(), smoothed.end());
  if (smoothed[*threshold_bin] > options.knee_fraction * peak) return result;

  const double edge = lo + (*threshold_bin + 1) * width;
  result.threshold = options.log_scale ? std::pow(10.0, edge) : edge;
  for (size_t i = 0; i < values.size(); ++i) {
    if (std::isfinite(values[i]) && bin_of(values[i]) > *threshold_bin) {
      result.outlier[i] = true;
      ++result.outlier_count;
    }
  }
  return result;
}

}  // namespace hecal::sim
