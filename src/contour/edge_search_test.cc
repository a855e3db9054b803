#include "hecal/contour/edge_search.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "hecal/contour/render.h"
#include "hecal/core/error.h"
#include "testing/options_validity.h"

namespace hecal::contour {
namespace {

// A straight edge through `through` with unit normal (cos a, sin a): foreground (200) on the −n
// side, background (50) on the +n side, rendered with area coverage and optical blur.
GrayImage HalfPlane(const Eigen::Vector2d& through, double angle, double noise, std::uint64_t seed,
                    double blur = 0.7) {
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
  options.blur_sigma = blur;
  options.noise_sigma = noise;
  options.seed = seed;
  return RenderPolygon(polygon, 64, 64, options);
}

// Edges at many angles and sub-pixel positions, searched from points up to 3 px away: the worst
// and RMS error of the located edge (noise-free images).
void EdgeErrors(double blur, double* worst, double* rms) {
  *worst = 0.0;
  double sum2 = 0.0;
  int searches = 0;
  for (int a = 0; a < 24; ++a) {
    const double angle = 0.13 + a * std::numbers::pi / 12.0;
    const Eigen::Vector2d n(std::cos(angle), std::sin(angle));
    const Eigen::Vector2d t(-n.y(), n.x());
    for (int s = 0; s < 4; ++s) {
      const Eigen::Vector2d through(31.0 + 0.23 * s, 32.0 - 0.17 * s);
      const GrayImage image = HalfPlane(through, angle, 0.0, 0, blur);
      for (double start : {-2.3, 0.0, 0.6, 2.9}) {
        for (double along : {0.0, 0.37, 0.71}) {
          const Eigen::Vector2d point = through + start * n + along * t;  // edge at −start
          const std::optional<EdgeHit> hit = SearchEdge(image, point, n, {});
          ASSERT_TRUE(hit.has_value()) << angle << " " << start;
          EXPECT_LT(hit->gradient, 0.0);  // bright → dark along +n
          *worst = std::max(*worst, std::abs(hit->offset + start));
          sum2 += (hit->offset + start) * (hit->offset + start);
          ++searches;
        }
      }
    }
  }
  EXPECT_EQ(searches, 24 * 4 * 4 * 3);
  *rms = std::sqrt(sum2 / searches);
}

TEST(SearchEdge, FindsARenderedEdgeToAFewHundredthsOfAPixel) {
  double worst = 0.0, rms = 0.0;
  EdgeErrors(0.7, &worst, &rms);  // the renderer's default optics
  EXPECT_LT(worst, 0.045);        // measured 0.035
  EXPECT_LT(rms, 0.022);          // measured 0.016
  // Without optical blur an area-sampled step is aliased ("pixel locking", render.h).
  EdgeErrors(0.0, &worst, &rms);
  EXPECT_LT(worst, 0.12);  // measured 0.097
  EXPECT_GT(rms, 0.025);   // measured 0.039: much worse than with the blur
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
  // A weak rise 0 → 30 at x = 8.5, then a bright bar (130) from x = 14.5 to x = 20.5.
  std::vector<float> v(30, 0.0f);
  for (int x = 9; x < 30; ++x) v[static_cast<std::size_t>(x)] = 30.0f;
  for (int x = 15; x <= 20; ++x) v[static_cast<std::size_t>(x)] = 130.0f;
  const GrayImage image = Columns(v);
  const Eigen::Vector2d right(1.0, 0.0);
  EdgeSearchOptions options;
  options.range = 7.0;
  // From x = 17 the rise at 14.5 and the fall at 20.5 are equally strong; polarity settles it.
  // The profiles are symmetric about each edge, so the parabola is exact.
  options.polarity = +1;
  std::optional<EdgeHit> hit = SearchEdge(image, {17.0, 2.0}, right, options);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(17.0 + hit->offset, 14.5, 1e-9);
  EXPECT_GT(hit->gradient, 0.0);
  options.polarity = -1;
  hit = SearchEdge(image, {17.0, 2.0}, right, options);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(17.0 + hit->offset, 20.5, 1e-9);
  EXPECT_LT(hit->gradient, 0.0);
  // Searching along −x flips the polarity.
  hit = SearchEdge(image, {17.0, 2.0}, -right, options);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(17.0 - hit->offset, 14.5, 1e-9);

  // The weak rise (a 30-level step: the σ_d = 1 px derivative peaks near 30/√(2π) ≈ 12 /px)
  // passes a threshold of 8 and fails one of 20.
  options.polarity = +1;
  options.range = 2.5;
  options.min_gradient = 8.0;
  hit = SearchEdge(image, {8.0, 2.0}, right, options);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(8.0 + hit->offset, 8.5, 1e-9);
  EXPECT_NEAR(hit->gradient, 30.0 / std::sqrt(2.0 * std::numbers::pi), 1.5);
  options.min_gradient = 20.0;
  EXPECT_FALSE(SearchEdge(image, {8.0, 2.0}, right, options).has_value());

  // An edge beyond the range (the peak would be at the end of the interval): nothing.
  options.min_gradient = 8.0;
  options.range = 1.5;
  EXPECT_FALSE(SearchEdge(image, {17.5, 2.0}, right, options).has_value());
  // A flat profile: nothing.
  EXPECT_FALSE(SearchEdge(Columns(std::vector<float>(30, 9.0f)), {17.0, 2.0}, right, options));
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
  EXPECT_THROW(SearchEdge(image, {5, 5}, {1, 0}, options), InputError);
  options = {};
  options.polarity = 2;
  EXPECT_THROW(SearchEdge(image, {5, 5}, {1, 0}, options), InputError);
}

TEST(EdgeSearchOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const EdgeSearchOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "EdgeSearchOptions.range", [](auto& o) { o.range = 0.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "EdgeSearchOptions.step", [](auto& o) { o.step = 11.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "EdgeSearchOptions.derivative_sigma",
                            [](auto& o) { o.derivative_sigma = -1.0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "EdgeSearchOptions.min_gradient",
                            [](auto& o) { o.min_gradient = -0.5; }));
  EXPECT_TRUE(
      RefusesNaming(defaults, "EdgeSearchOptions.polarity", [](auto& o) { o.polarity = 2; }));
}

}  // namespace
}  // namespace hecal::contour
