#include "hecal/contour/render.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "hecal/contour/perspective_view.h"
#include "testing/options_validity.h"

namespace hecal::contour {
namespace {

double ShoelaceArea(const Eigen::Matrix2Xd& p) {
  double twice = 0.0;
  for (Eigen::Index i = 0; i < p.cols(); ++i) {
    const Eigen::Index j = (i + 1) % p.cols();
    twice += p(0, i) * p(1, j) - p(0, j) * p(1, i);
  }
  return 0.5 * twice;
}

// Sutherland–Hodgman clipping of `subject` to the axis-aligned box [x0, x1] × [y0, y1]: the exact
// part of a (possibly concave) polygon inside one pixel; its shoelace area is exact.
std::vector<Eigen::Vector2d> ClipToBox(std::vector<Eigen::Vector2d> subject, double x0, double x1,
                                       double y0, double y1) {
  const auto clip = [&](int axis, double bound, bool keep_below) {
    std::vector<Eigen::Vector2d> out;
    const std::size_t n = subject.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector2d& a = subject[i];
      const Eigen::Vector2d& b = subject[(i + 1) % n];
      const bool a_in = keep_below ? a(axis) <= bound : a(axis) >= bound;
      const bool b_in = keep_below ? b(axis) <= bound : b(axis) >= bound;
      if (a_in) out.push_back(a);
      if (a_in != b_in) {
        const double t = (bound - a(axis)) / (b(axis) - a(axis));
        out.push_back(a + t * (b - a));
      }
    }
    subject = out;
  };
  clip(0, x0, false);
  clip(0, x1, true);
  clip(1, y0, false);
  clip(1, y1, true);
  return subject;
}

double ExactPixelCoverage(const Eigen::Matrix2Xd& polygon, int x, int y) {
  std::vector<Eigen::Vector2d> subject;
  for (Eigen::Index i = 0; i < polygon.cols(); ++i) subject.push_back(polygon.col(i));
  const std::vector<Eigen::Vector2d> clipped =
      ClipToBox(subject, x - 0.5, x + 0.5, y - 0.5, y + 0.5);
  if (clipped.size() < 3) return 0.0;
  Eigen::Matrix2Xd p(2, static_cast<Eigen::Index>(clipped.size()));
  for (std::size_t i = 0; i < clipped.size(); ++i) p.col(static_cast<Eigen::Index>(i)) = clipped[i];
  return std::abs(ShoelaceArea(p));
}

double Sum(const GrayImage& image) {
  double sum = 0.0;
  for (float v : image.pixels()) sum += v;
  return sum;
}

// A concave, non-symmetric polygon with edges at many slopes.
Eigen::Matrix2Xd Arrow() {
  Eigen::Matrix2Xd p(2, 7);
  p << 5.3, 30.7, 31.2, 44.9, 31.9, 30.1, 6.2,  //
      10.4, 8.1, 2.6, 17.3, 33.8, 25.2, 27.9;
  return p;
}

TEST(PolygonCoverage, PixelAlignedRectangleIsExact) {
  Eigen::Matrix2Xd rect(2, 4);
  rect << 1.5, 4.5, 4.5, 1.5,  //
      2.5, 2.5, 5.5, 5.5;      // pixels x = 2..4, y = 3..5 fully inside
  const GrayImage c = PolygonCoverage(rect, 8, 8, 4);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      const bool inside = x >= 2 && x <= 4 && y >= 3 && y <= 5;
      EXPECT_NEAR(c.at(x, y), inside ? 1.0 : 0.0, 1e-6) << x << "," << y;
    }
  }
}

TEST(PolygonCoverage, VerticalEdgesAreExactInX) {
  Eigen::Matrix2Xd rect(2, 4);
  rect << 1.8, 4.1, 4.1, 1.8,  //
      0.5, 0.5, 2.5, 2.5;
  const GrayImage c = PolygonCoverage(rect, 6, 4, 1);
  EXPECT_NEAR(c.at(1, 1), 0.0, 1e-6);  // pixel 1 covers [0.5, 1.5]: outside
  EXPECT_NEAR(c.at(2, 1), 0.7, 1e-6);  // pixel 2 covers [1.5, 2.5]: inside from 1.8
  EXPECT_NEAR(c.at(3, 1), 1.0, 1e-6);
  EXPECT_NEAR(c.at(4, 1), 0.6, 1e-6);  // [3.5, 4.1]
  EXPECT_NEAR(c.at(5, 1), 0.0, 1e-6);
}

TEST(PolygonCoverage, MatchesTheExactAreaPerPixelAndInTotal) {
  const Eigen::Matrix2Xd polygon = Arrow();
  const int n = 16;
  const GrayImage c = PolygonCoverage(polygon, 50, 40, n);
  double worst = 0.0;
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 50; ++x) {
      worst = std::max(worst, std::abs(c.at(x, y) - ExactPixelCoverage(polygon, x, y)));
    }
  }
  // Per pixel: exact in x; in y the midpoint rule misses at most half a sub-row where a vertex
  // or a near-horizontal edge lies inside the pixel.
  EXPECT_LT(worst, 1.0 / n);
  // In total: the area of the polygon (≈ 800 px²) to a small fraction of a pixel.
  EXPECT_NEAR(Sum(c), std::abs(ShoelaceArea(polygon)), 0.05);
  // Orientation does not matter (even–odd rule).
  const GrayImage reversed = PolygonCoverage(polygon.rowwise().reverse(), 50, 40, n);
  EXPECT_NEAR(Sum(reversed), Sum(c), 1e-9);
}

TEST(PolygonCoverage, DiscAreaConvergesWithSupersampling) {
  const int m = 400;
  Eigen::Matrix2Xd disc(2, m);
  for (int k = 0; k < m; ++k) {
    const double a = 2 * std::numbers::pi * k / m;
    disc.col(k) << 30.37 + 17.3 * std::cos(a), 25.81 + 17.3 * std::sin(a);
  }
  const double area = ShoelaceArea(disc);
  EXPECT_NEAR(Sum(PolygonCoverage(disc, 64, 52, 1)), area, 2.0);
  // The midpoint rule's error is largest at the top and bottom of a curved outline, where the
  // width varies as a square root: O(n^{-3/2}) (measured: 0.033 at n = 16, 0.0009 at n = 64).
  EXPECT_NEAR(Sum(PolygonCoverage(disc, 64, 52, 16)), area, 0.06);
  EXPECT_NEAR(Sum(PolygonCoverage(disc, 64, 52, 64)), area, 0.004);
}

TEST(PolygonCoverage, ClipsToTheImage) {
  Eigen::Matrix2Xd big(2, 4);
  big << -10, 20, 20, -10,  //
      -10, -10, 20, 20;
  const GrayImage c = PolygonCoverage(big, 5, 4, 2);
  EXPECT_NEAR(Sum(c), 20.0, 1e-9);
  EXPECT_THROW(PolygonCoverage(Eigen::Matrix2Xd::Zero(2, 2), 5, 5, 2), std::invalid_argument);
  EXPECT_THROW(PolygonCoverage(big, 5, 5, 0), std::invalid_argument);
}

TEST(RenderPolygon, BlurKeepsTheMassAndSpreadsAStepLikeAGaussian) {
  // A vertical step at x = 20 (pixel-aligned: pixels x ≤ 19 are fully inside).
  Eigen::Matrix2Xd half(2, 4);
  half << -100, 19.5, 19.5, -100,  //
      -100, -100, 100, 100;
  GrayImage image = PolygonCoverage(half, 40, 8, 4);
  const double mass = [&] {
    double m = 0.0;
    for (int x = 0; x < 40; ++x) m += image.at(x, 4);
    return m;
  }();
  GaussianBlur(&image, 1.0);
  double blurred_mass = 0.0;
  for (int x = 0; x < 40; ++x) blurred_mass += image.at(x, 4);
  EXPECT_NEAR(blurred_mass, mass, 1e-4);  // away from the image borders nothing is lost
  // The blurred step at pixel centres: Σ_{i ≤ 19} G(x − i), G the sampled unit Gaussian; by
  // symmetry pixels 19 and 20 sum to 1, and at x = 19 it exceeds ½ by about Φ(0.5) − ½ = 0.19.
  EXPECT_NEAR(image.at(19, 4) + image.at(20, 4), 1.0, 1e-6);
  EXPECT_NEAR(image.at(19, 4), 0.69, 0.01);
  EXPECT_NEAR(image.at(15, 4), 1.0, 1e-3);
  EXPECT_THROW(GaussianBlur(&image, -1.0), std::invalid_argument);
}

TEST(RenderPolygon, LevelsNoiseAndQuantisation) {
  Eigen::Matrix2Xd rect(2, 4);
  rect << -0.5, 99.5, 99.5, -0.5,  //
      -0.5, -0.5, 49.5, 49.5;      // the top half of a 100 × 100 image
  RenderOptions options;
  options.foreground = 200.0;
  options.background = 40.0;
  options.blur_sigma = 0.0;
  const GrayImage clean = RenderPolygon(rect, 100, 100, options);
  EXPECT_FLOAT_EQ(clean.at(10, 10), 200.0f);
  EXPECT_FLOAT_EQ(clean.at(10, 90), 40.0f);

  options.noise_sigma = 3.0;
  options.seed = 7;
  const GrayImage noisy = RenderPolygon(rect, 100, 100, options);
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t i = 0; i < noisy.pixels().size(); ++i) {
    const double d = noisy.pixels()[i] - clean.pixels()[i];
    sum += d;
    sum2 += d * d;
  }
  const double count = static_cast<double>(noisy.pixels().size());
  EXPECT_NEAR(sum / count, 0.0, 4 * 3.0 / std::sqrt(count));
  EXPECT_NEAR(std::sqrt(sum2 / count), 3.0, 0.05);  // sd of the sd ≈ 3/√(2·10⁴) = 0.02
  // Reproducible per seed, different across seeds.
  EXPECT_EQ(RenderPolygon(rect, 100, 100, options).pixels(), noisy.pixels());
  options.seed = 8;
  EXPECT_NE(RenderPolygon(rect, 100, 100, options).pixels(), noisy.pixels());

  options.quantize = true;
  options.foreground = 300.0;
  const GrayImage quantized = RenderPolygon(rect, 100, 100, options);
  for (float v : quantized.pixels()) {
    EXPECT_EQ(v, std::round(v));
    EXPECT_GE(v, 0.0f);
    EXPECT_LE(v, 255.0f);
  }
  EXPECT_EQ(quantized.at(50, 20), 255.0f);
}

TEST(RenderPlanarTarget, TemplateViewIsTheScaledTargetAtThePrincipalPoint) {
  Eigen::Matrix2Xd q(2, 6);
  q << 90, 40, -60, -100, -30, 70,  //
      10, 70, 60, -20, -75, -50;    // mm
  const ClosedBSpline target(q);
  const ContourCamera camera{6024.0, 5000.0};
  const Eigen::Vector2d pp(160.3, 120.7);
  const Eigen::Matrix2Xd outline = PerspectiveOutline(target, Eigen::Matrix3d::Identity(),
                                                      Eigen::Vector3d::Zero(), camera, pp, 32);
  ASSERT_EQ(outline.cols(), 6 * 32);
  const Eigen::Matrix2Xd expected = (camera.focal / camera.z0 * target.Sample(32)).colwise() + pp;
  EXPECT_LT((outline - expected).cwiseAbs().maxCoeff(), 1e-9);

  RenderOptions options;
  const GrayImage image =
      RenderPlanarTarget(target, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), camera, pp,
                         320, 240, options, 64);
  // The foreground area is the target's area × (f/Z0)² (the fine outline is a polygon within
  // 1e-3 of the curve's area).
  double covered = 0.0;
  for (float v : image.pixels())
    covered += (v - options.background) / (options.foreground - options.background);
  const double scale = camera.focal / camera.z0;
  EXPECT_NEAR(covered, std::abs(target.SignedArea()) * scale * scale, 1e-3 * covered);
  // Inside at the principal point, background in the corner.
  EXPECT_NEAR(image.at(160, 120), options.foreground, 1e-4);
  EXPECT_NEAR(image.at(0, 0), options.background, 1e-4);
}

TEST(RenderPlanarTarget, ATranslationShiftsTheImageByFTOverZ) {
  Eigen::Matrix2Xd q(2, 5);
  q << 50, 0, -50, -40, 30,  //
      0, 40, 10, -30, -40;
  const ClosedBSpline target(q);
  const ContourCamera camera{1000.0, 2000.0};
  const Eigen::Vector3d t(100.0, -60.0, -400.0);
  const Eigen::Matrix2Xd shifted =
      PerspectiveOutline(target, Eigen::Matrix3d::Identity(), t, camera, Eigen::Vector2d(5, 6), 8);
  const double z = camera.z0 + t.z();
  for (Eigen::Index i = 0; i < shifted.cols(); ++i) {
    const Eigen::Vector2d p = target.Sample(8).col(i);
    EXPECT_NEAR(shifted(0, i), 5 + camera.focal * (p.x() + t.x()) / z, 1e-9);
    EXPECT_NEAR(shifted(1, i), 6 + camera.focal * (p.y() + t.y()) / z, 1e-9);
  }
}

TEST(RenderOptions, IsValidNamesTheField) {
  using testing::RefusesNaming;
  const RenderOptions defaults;
  EXPECT_TRUE(testing::IsValidOptions(defaults));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(
      RefusesNaming(defaults, "RenderOptions.foreground", [&](auto& o) { o.foreground = nan; }));
  EXPECT_TRUE(
      RefusesNaming(defaults, "RenderOptions.background", [&](auto& o) { o.background = nan; }));
  EXPECT_TRUE(
      RefusesNaming(defaults, "RenderOptions.supersampling", [](auto& o) { o.supersampling = 0; }));
  EXPECT_TRUE(
      RefusesNaming(defaults, "RenderOptions.blur_sigma", [](auto& o) { o.blur_sigma = -0.1; }));
  EXPECT_TRUE(
      RefusesNaming(defaults, "RenderOptions.noise_sigma", [&](auto& o) { o.noise_sigma = nan; }));
}

}  // namespace
}  // namespace hecal::contour
