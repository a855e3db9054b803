#include "hecal/sim/summary_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace hecal::sim {
namespace {

std::vector<double> SortedFinite(std::span<const double> values) {
  std::vector<double> finite;
  finite.reserve(values.size());
  for (double v : values) {
    if (std::isfinite(v)) finite.push_back(v);
  }
  std::sort(finite.begin(), finite.end());
  return finite;
}

double SortedQuantile(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
  const double h = std::clamp(p, 0.0, 1.0) * static_cast<double>(sorted.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(h));
  const size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (h - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

}  // namespace

double Quantile(std::span<const double> values, double p) {
  return SortedQuantile(SortedFinite(values), p);
}

SummaryStatistics Summarize(std::span<const double> values) {
  const std::vector<double> sorted = SortedFinite(values);
  SummaryStatistics s;
  s.count = static_cast<int>(sorted.size());
  s.failures = static_cast<int>(values.size()) - s.count;
  if (sorted.empty()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    s.median = s.rmse = s.p10 = s.p90 = s.max = nan;
    return s;
  }
  double sum_sq = 0.0;
  for (double v : sorted) sum_sq += v * v;
  s.rmse = std::sqrt(sum_sq / static_cast<double>(sorted.size()));
  s.median = SortedQuantile(sorted, 0.5);
  s.p10 = SortedQuantile(sorted, 0.1);
  s.p90 = SortedQuantile(sorted, 0.9);
  s.max = sorted.back();
  return s;
}

}  // namespace hecal::sim
