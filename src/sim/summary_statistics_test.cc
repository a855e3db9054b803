#include "hecal/sim/summary_statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace hecal::sim {
namespace {

TEST(Summarize, HandComputedValues) {
  // Sorted: 1 2 3 4 5 6 7 8 9 10 (given shuffled).
  const std::vector<double> v = {7, 2, 10, 4, 1, 9, 3, 6, 5, 8};
  const SummaryStatistics s = Summarize(v);
  EXPECT_EQ(s.count, 10);
  EXPECT_EQ(s.failures, 0);
  EXPECT_DOUBLE_EQ(s.median, 5.5);  // h = 4.5
  EXPECT_DOUBLE_EQ(s.p10, 1.9);     // h = 0.9: 1 + 0.9 (2 − 1)
  EXPECT_DOUBLE_EQ(s.p90, 9.1);     // h = 8.1: 9 + 0.1 (10 − 9)
  EXPECT_DOUBLE_EQ(s.max, 10.0);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(385.0 / 10.0));  // Σ k² for k = 1..10 is 385
}

TEST(Summarize, OddCountMedianIsTheMiddleValue) {
  const std::vector<double> v = {3.0, -1.0, 2.0};
  const SummaryStatistics s = Summarize(v);
  EXPECT_DOUBLE_EQ(s.median, 2.0);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(14.0 / 3.0));
  EXPECT_DOUBLE_EQ(s.p10, -1.0 + 0.2 * 3.0);  // h = 0.2 between −1 and 2
}

TEST(Summarize, NonFiniteValuesAreFailuresAndExcluded) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> v = {nan, 4.0, inf, 2.0, -inf};
  const SummaryStatistics s = Summarize(v);
  EXPECT_EQ(s.count, 2);
  EXPECT_EQ(s.failures, 3);
  EXPECT_DOUBLE_EQ(s.median, 3.0);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(10.0));
  EXPECT_DOUBLE_EQ(s.max, 4.0);
}

TEST(Summarize, NoFiniteValueGivesNaN) {
  const std::vector<double> v = {std::numeric_limits<double>::quiet_NaN()};
  const SummaryStatistics s = Summarize(v);
  EXPECT_EQ(s.count, 0);
  EXPECT_EQ(s.failures, 1);
  EXPECT_TRUE(std::isnan(s.median));
  EXPECT_TRUE(std::isnan(s.rmse));
  EXPECT_TRUE(std::isnan(Summarize(std::vector<double>{}).p90));
}

TEST(Quantile, EndsAndSingleValue) {
  const std::vector<double> v = {5.0, 1.0, 3.0};
  EXPECT_DOUBLE_EQ(Quantile(v, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(Quantile(v, 1.0), 5.0);
  EXPECT_DOUBLE_EQ(Quantile(v, 0.25), 2.0);
  EXPECT_DOUBLE_EQ(Quantile(std::vector<double>{7.0}, 0.9), 7.0);
}

}  // namespace
}  // namespace hecal::sim
