#include "hecal/contour/edge_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "hecal/contour/render.h"

namespace hecal::contour {
namespace {

// A straight edge through `through` with unit normal (cos a, sin a): foreground (200) on the −n
// side, background (50) on the +n side, rendered with area coverage.
GrayImage HalfPlane(const Eigen::Vector2d& through, double angle, double noise,
                    std::uint64_t seed) {
  const Eigen::Vector2d n(std::cos(angle), std::sin(angle));
  const Eigen::Vector2d t(-n.y(), n.x());
  Eigen::Matrix2Xd polygon(2, 4);  // a big square on the −n side
  polygon.col(0) = through + 500 * t;
  polygon.col(1) = through - 500 * t;
  polygon.col(2) = through - 500 * t - 1000 * n;
  polygon.col(3) = through + 500 * t - 1000 * n;
  RenderOptions options;
  options.foreground = 200.0;
  options.background = 50.0;
  options.supersampling = 32;
  options.noise_sigma = noise;
  options.seed = seed;
  return RenderPolygon(polygon, 64, 64, options);
}

TEST(SearchEdge, FindsARenderedEdgeToAFewHundredthsOfAPixel) {
  // Edges at many angles and sub-pixel positions, searched from points 0…4 px away.
  double worst = 0.0;
  int searches = 0;
  for (int a = 0; a < 12; ++a) {
    const double angle = 0.13 + a * std::numbers::pi / 6.0;
    const Eigen::Vector2d n(std::cos(angle), std::sin(angle));
    for (int s = 0; s < 5; ++s) {
      const Eigen::Vector2d through(31.0 + 0.23 * s, 32.0 - 0.17 * s);
      const GrayImage image = HalfPlane(through, angle, 0.0, 0);
      for (double start : {-4.0, -1.3, 0.0, 0.6, 2.9}) {
        const Eigen::Vector2d point = through + start * n;  // the edge is at offset −start
        const std::optional<EdgeHit> hit = SearchEdge(image, point, n, {});
        ASSERT_TRUE(hit.has_value()) << angle << " " << start;
        EXPECT_LT(hit->gradient, 0.0);  // bright → dark along +n
        worst = std::max(worst, std::abs(hit->offset + start));
        ++searches;
      }
    }
  }
  EXPECT_EQ(searches, 300);
  EXPECT_LT(worst, 0.06);
}

TEST(SearchEdge, NoiseGivesAnUnbiasedSpreadOfAFewHundredthsOfAPixel) {
  const double angle = 0.4;
  const Eigen::Vector2d n(std::cos(angle), std::sin(angle));
  const Eigen::Vector2d through(32.2, 31.7);
  double sum = 0.0, sum2 = 0.0;
  const int trials = 200;
  for (int seed = 0; seed < trials; ++seed) {
    const GrayImage image = HalfPlane(through, angle, 3.0, static_cast<std::uint64_t>(seed));
    const std::optional<EdgeHit> hit = SearchEdge(image, through + 1.1 * n, n, {});
    ASSERT_TRUE(hit.has_value());
    const double error = hit->offset + 1.1;
    sum += error;
    sum2 += error * error;
  }
  const double mean = sum / trials;
  const double sd = std::sqrt(sum2 / trials - mean * mean);
  EXPECT_LT(std::abs(mean), 0.05);
  EXPECT_GT(sd, 0.005);  // noise does move the edge …
  EXPECT_LT(sd, 0.1);    // … by a small fraction of a pixel at contrast 150 / σ 3
}

// A profile image: columns with given intensities (the same in every row).
GrayImage Columns(const std::vector<float>& values) {
  GrayImage image(static_cast<int>(values.size()), 5);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < image.width(); ++x) image.at(x, y) = values[static_cast<std::size_t>(x)];
  }
  return image;
}

TEST(SearchEdge, PolarityThresholdAndRange) {
  // Bright bar from x = 8 to x = 14 on 0; a weaker rise at x = 4.5 (0 → 30).
  std::vector<float> v(24, 0.0f);
  for (int x = 5; x < 24; ++x) v[static_cast<std::size_t>(x)] = 30.0f;
  for (int x = 9; x <= 14; ++x) v[static_cast<std::size_t>(x)] = 130.0f;
  const GrayImage image = Columns(v);
  const Eigen::Vector2d right(1.0, 0.0);
  EdgeSearchOptions options;
  options.range = 7.0;
  // Either polarity: the strongest is the rise at 8.5 (100 levels) or the fall at 14.5 (100):
  // from x = 10 the rise is closer to the centre but both are equal; polarity settles it.
  options.polarity = +1;
  std::optional<EdgeHit> hit = SearchEdge(image, {11.0, 2.0}, right, options);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(11.0 + hit->offset, 8.5, 1e-9);  // symmetric profile: the parabola is exact
  EXPECT_GT(hit->gradient, 0.0);
  options.polarity = -1;
  hit = SearchEdge(image, {11.0, 2.0}, right, options);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(11.0 + hit->offset, 14.5, 1e-9);
  EXPECT_LT(hit->gradient, 0.0);
  // Searching along −x flips the polarity.
  hit = SearchEdge(image, {11.0, 2.0}, -right, options);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(11.0 - hit->offset, 8.5, 1e-9);

  // The weak rise (30 levels over 1 px → 15 /px after the 2 px derivative) passes a threshold of
  // 10 and fails one of 20.
  options.polarity = +1;
  options.range = 2.5;
  options.min_gradient = 10.0;
  hit = SearchEdge(image, {4.0, 2.0}, right, options);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(4.0 + hit->offset, 4.5, 1e-9);
  options.min_gradient = 20.0;
  EXPECT_FALSE(SearchEdge(image, {4.0, 2.0}, right, options).has_value());

  // An edge beyond the range (the peak would be at the end of the interval): nothing.
  options.min_gradient = 10.0;
  options.range = 1.5;
  EXPECT_FALSE(SearchEdge(image, {11.5, 2.0}, right, options).has_value());
  // A flat profile: nothing.
  EXPECT_FALSE(SearchEdge(Columns(std::vector<float>(24, 9.0f)), {11.0, 2.0}, right, options));
}

TEST(SearchEdge, ProfilesLeavingTheImageAreRejected) {
  std::vector<float> v(24, 0.0f);
  for (int x = 12; x < 24; ++x) v[static_cast<std::size_t>(x)] = 100.0f;
  const GrayImage image = Columns(v);
  EdgeSearchOptions options;
  options.range = 5.0;
  EXPECT_TRUE(SearchEdge(image, {11.0, 2.0}, {1.0, 0.0}, options).has_value());
  EXPECT_FALSE(SearchEdge(image, {3.0, 2.0}, {1.0, 0.0}, options).has_value());
  EXPECT_FALSE(SearchEdge(image, {11.0, 2.0}, {0.0, 1.0}, options).has_value());  // 5 rows only
}

TEST(SearchEdge, RejectsBadOptions) {
  const GrayImage image(10, 10);
  EdgeSearchOptions options;
  EXPECT_THROW(SearchEdge(image, {5, 5}, {0, 0}, options), std::invalid_argument);
  options.step = 0.0;
  EXPECT_THROW(SearchEdge(image, {5, 5}, {1, 0}, options), std::invalid_argument);
  options = {};
  options.polarity = 2;
  EXPECT_THROW(SearchEdge(image, {5, 5}, {1, 0}, options), std::invalid_argument);
}

}  // namespace
}  // namespace hecal::contour
