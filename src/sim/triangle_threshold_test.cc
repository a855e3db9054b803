#include "hecal/sim/triangle_threshold.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "hecal/core/random_draws.h"
#include "testing/options_validity.h"

namespace hecal::sim {
namespace {

TEST(MovingAverage, CentredWindowTruncatedAtTheEnds) {
  const std::vector<double> h = {0.0, 3.0, 0.0, 6.0};
  const std::vector<double> s = MovingAverage(h, 3);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_DOUBLE_EQ(s[0], 1.5);  // (0 + 3) / 2
  EXPECT_DOUBLE_EQ(s[1], 1.0);  // (0 + 3 + 0) / 3
  EXPECT_DOUBLE_EQ(s[2], 3.0);  // (3 + 0 + 6) / 3
  EXPECT_DOUBLE_EQ(s[3], 3.0);  // (0 + 6) / 2
  EXPECT_EQ(MovingAverage(h, 1), h);
  const std::vector<double> flat(7, 2.0);
  EXPECT_EQ(MovingAverage(flat, 5), flat);
}

TEST(TriangleThresholdBin, HandComputedExample) {
  // Peak at 1 (height 10); the line ends at the last bin (8, 0): line(k) = 10 (8 − k) / 7.
  // Gaps below it: k=2: 2.571, k=3: 5.143, k=4: 4.714, k=5: 3.286, k=6: 1.857, k=7: 0.929.
  const std::vector<double> h = {0.0, 10.0, 6.0, 2.0, 1.0, 1.0, 1.0, 0.5, 0.0};
  const std::optional<int> bin = TriangleThresholdBin(h);
  ASSERT_TRUE(bin.has_value());
  EXPECT_EQ(*bin, 3);
}

TEST(TriangleThresholdBin, SecondPeakFarOutIsBeyondTheKnee) {
  // A bulk at bins 0–2 and a small cluster of outliers at 8–9: the knee is right after the bulk.
  // line(k) = 50 (10 − k) / 10 from the peak at 0 to (10, 0): k=1: 45−30=15, k=2: 40−5=35,
  // k=3: 35−0=35 (tie → the first), ...
  const std::vector<double> h = {50.0, 30.0, 5.0, 0.0, 0.0, 0.0, 0.0, 0.0, 2.0, 1.0, 0.0};
  const std::optional<int> bin = TriangleThresholdBin(h);
  ASSERT_TRUE(bin.has_value());
  EXPECT_EQ(*bin, 2);
}

TEST(TriangleThresholdBin, TheLineEndsAtTheFarthestBinsHeight) {
  // Line from (0, 8) to (3, 4): line(1) = 6.667 (gap 4.667), line(2) = 5.333 (gap 3.333).
  const std::optional<int> bin = TriangleThresholdBin(std::vector<double>{8.0, 2.0, 2.0, 4.0});
  ASSERT_TRUE(bin.has_value());
  EXPECT_EQ(*bin, 1);
}

TEST(TriangleThresholdBin, NoBinBelowTheLineMeansNoThreshold) {
  // Concave decay: every bin after the peak is above the line from (0, 10) to (4, 0).
  EXPECT_FALSE(TriangleThresholdBin(std::vector<double>{10.0, 9.5, 9.0, 8.0, 0.0}).has_value());
  // Peak at the last bin: nothing after it.
  EXPECT_FALSE(TriangleThresholdBin(std::vector<double>{1.0, 2.0, 3.0}).has_value());
  EXPECT_FALSE(TriangleThresholdBin(std::vector<double>{}).has_value());
}

TEST(TriangleThreshold, FarOutliersAreMarkedAndTheBulkIsNot) {
  std::mt19937_64 rng(7);
  std::lognormal_distribution<double> bulk(0.0, 0.3);  // around 1, within a factor ~3
  std::vector<double> values;
  for (int i = 0; i < 190; ++i) values.push_back(bulk(rng));
  hecal::UniformRealDistribution far(100.0, 1000.0);
  for (int i = 0; i < 10; ++i) values.push_back(far(rng));
  const TriangleThresholdResult result = TriangleThreshold(values);
  EXPECT_EQ(result.outlier_count, 10);
  for (int i = 0; i < 200; ++i) EXPECT_EQ(result.outlier[i], i >= 190) << i;
  EXPECT_GT(result.threshold, 3.0);
  EXPECT_LT(result.threshold, 100.0);
}

double MaxwellSample(std::mt19937_64& rng) {
  hecal::NormalDistribution normal;
  const double a = normal(rng), b = normal(rng), c = normal(rng);
  return std::sqrt(a * a + b * b + c * c);
}

TEST(TriangleThreshold, CleanMaxwellSamplesGetFewFalseOutliers) {
  // The rotation-error angle under isotropic noise is Maxwell distributed: the thesis' "no
  // outliers" regime. Over 50 seeded samples of 200, at most 1 marked in any one.
  std::mt19937_64 rng(11);
  int worst = 0;
  for (int rep = 0; rep < 50; ++rep) {
    std::vector<double> values;
    for (int i = 0; i < 200; ++i) values.push_back(MaxwellSample(rng));
    worst = std::max(worst, TriangleThreshold(values).outlier_count);
  }
  EXPECT_LE(worst, 1);
}

TEST(TriangleThreshold, ScaleMixturesGetFewFalseOutliers) {
  // Errors of data sets with different conditioning: Maxwell × lognormal(0, 0.5).
  std::mt19937_64 rng(13);
  std::lognormal_distribution<double> scale(0.0, 0.5);
  int worst = 0;
  for (int rep = 0; rep < 50; ++rep) {
    std::vector<double> values;
    for (int i = 0; i < 200; ++i) {
      const double maxwell = MaxwellSample(rng);  // drawn before the scale
      values.push_back(maxwell * scale(rng));
    }
    worst = std::max(worst, TriangleThreshold(values).outlier_count);
  }
  EXPECT_LE(worst, 3);
}

TEST(TriangleThreshold, AKneeOnTheShoulderOfTheBulkIsNotATail) {
  // Symmetric on the log axis (lognormal): the triangle's knee is on the bulk's shoulder, high
  // above 10% of the peak, so nothing is marked; without the knee-height rule it would cut.
  std::mt19937_64 rng(17);
  std::lognormal_distribution<double> lognormal(0.0, 0.7);
  std::vector<double> values;
  for (int i = 0; i < 200; ++i) values.push_back(lognormal(rng));
  EXPECT_EQ(TriangleThreshold(values).outlier_count, 0);
  TriangleThresholdOptions options;
  options.knee_fraction = 1.0;
  EXPECT_GT(TriangleThreshold(values, options).outlier_count, 0);
}

TEST(TriangleThreshold, LinearScaleOptionCutsAtTheUpperEdgeOfTheKneeBin) {
  // Ten values: eight in [0, 1), one at 5 and one at 10. Linear, 5 bins of width 2 over [0, 10]
  // plus 2 empty ones: {8, 0, 1, 0, 1, 0, 0}; window 1 (no smoothing). Line from (0, 8) to
  // (6, 0): gaps k=1: 6.667, k=2: 4.333, k=3: 4, k=4: 1.667, k=5: 1.333 → bin 1, threshold at its
  // upper edge 4.
  std::vector<double> values = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 5.0, 10.0};
  TriangleThresholdOptions options;
  options.log_scale = false;
  options.smoothing_window = 1;
  const TriangleThresholdResult result = TriangleThreshold(values, options);
  EXPECT_DOUBLE_EQ(result.threshold, 4.0);
  EXPECT_EQ(result.outlier_count, 2);
  EXPECT_TRUE(result.outlier[8]);
  EXPECT_TRUE(result.outlier[9]);
}

TEST(TriangleThreshold, DegenerateInputsHaveNoOutliers) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(TriangleThreshold(std::vector<double>{1.0, 1000.0}).outlier_count, 0);
  EXPECT_EQ(TriangleThreshold(std::vector<double>(50, 2.0)).outlier_count, 0);
  EXPECT_EQ(TriangleThreshold(std::vector<double>(50, 0.0)).outlier_count, 0);
  EXPECT_TRUE(std::isinf(TriangleThreshold(std::vector<double>{}).threshold));
  // Non-finite values are neither binned nor marked.
  std::vector<double> values(100, 1.0);
  for (int i = 0; i < 100; ++i) values[i] = 1.0 + 0.01 * i;
  values.push_back(nan);
  values.push_back(inf);
  const TriangleThresholdResult result = TriangleThreshold(values);
  EXPECT_FALSE(result.outlier[100]);
  EXPECT_FALSE(result.outlier[101]);
}

TEST(TriangleThreshold, ZerosAreBinnedWithTheSmallestPositiveValue) {
  // Noise-free errors can be exactly 0; they join the bulk, never the tail.
  std::vector<double> values;
  for (int i = 0; i < 40; ++i) values.push_back(i % 4 == 0 ? 0.0 : 1e-12 * (1.0 + 0.05 * i));
  values.push_back(1e-3);
  const TriangleThresholdResult result = TriangleThreshold(values);
  EXPECT_EQ(result.outlier_count, 1);
  EXPECT_TRUE(result.outlier.back());
}

TEST(TriangleThreshold, ValuesBelowTheFloorAreNeverOutliers) {
  // Rounding noise with a few larger rounding errors: without a floor those are a tail three
  // decades out and get marked; with a floor above them nothing is, while a real outlier still is.
  std::vector<double> values;
  for (int i = 0; i < 100; ++i) values.push_back(1e-16 * (1.0 + 0.09 * i));
  for (int i = 0; i < 3; ++i) values.push_back(1e-12);
  EXPECT_EQ(TriangleThreshold(values).outlier_count, 3);
  TriangleThresholdOptions options;
  options.floor = 1e-9;
  EXPECT_EQ(TriangleThreshold(values, options).outlier_count, 0);
  values.push_back(1e-3);
  const TriangleThresholdResult result = TriangleThreshold(values, options);
  EXPECT_EQ(result.outlier_count, 1);
  EXPECT_TRUE(result.outlier.back());
}

TEST(TriangleThresholdOptions, IsValidNamesTheField) {
  using hecal::testing::RefusesNaming;
  const TriangleThresholdOptions defaults;
  EXPECT_TRUE(hecal::testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "TriangleThresholdOptions.min_bins",
                            [](auto& o) { o.min_bins = 0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "TriangleThresholdOptions.max_bins",
                            [](auto& o) { o.max_bins = 4; }));
  EXPECT_TRUE(RefusesNaming(defaults, "TriangleThresholdOptions.padding_bins",
                            [](auto& o) { o.padding_bins = -1; }));
  EXPECT_TRUE(RefusesNaming(defaults, "TriangleThresholdOptions.smoothing_window",
                            [](auto& o) { o.smoothing_window = 4; }));
  EXPECT_TRUE(RefusesNaming(defaults, "TriangleThresholdOptions.floor",
                            [](auto& o) { o.floor = std::numeric_limits<double>::infinity(); }));
  EXPECT_TRUE(RefusesNaming(defaults, "TriangleThresholdOptions.knee_fraction",
                            [](auto& o) { o.knee_fraction = 0.0; }));
}

}  // namespace
}  // namespace hecal::sim
