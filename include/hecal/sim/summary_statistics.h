// Summary statistics of Monte-Carlo trial errors (the thesis study, docs/thesis-study.md): median,
// RMSE, 10th and 90th percentiles, maximum, and the number of failed trials.
//
//  - Non-finite values (a solver threw or returned NaN/inf) are failures: counted, and left out
//    of every statistic.
//  - Percentiles interpolate linearly between order statistics (Hyndman & Fan type 7, the default
//    of R and NumPy): p-quantile of sorted x_0..x_{n−1} is x_⌊h⌋ + (h − ⌊h⌋)(x_⌊h⌋+1 − x_⌊h⌋),
//    h = p (n − 1). The median is the 0.5 quantile.
//  - RMSE = sqrt(mean(x²)): the values are errors against the truth, so this is the root mean
//    square error, comparable with a first-order covariance bound sqrt(trace Σ).
//  - With no finite value, every statistic is NaN.
#pragma once

#include <span>

namespace hecal::sim {

struct SummaryStatistics {
  int count = 0;     // finite values
  int failures = 0;  // non-finite values
  double median = 0.0;
  double rmse = 0.0;
  double p10 = 0.0;
  double p90 = 0.0;
  double max = 0.0;
};

SummaryStatistics Summarize(std::span<const double> values);

// Type-7 quantile of the finite values, p in [0, 1]; NaN when there is none.
double Quantile(std::span<const double> values, double p);

}  // namespace hecal::sim
