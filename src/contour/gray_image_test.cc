#include "hecal/contour/gray_image.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace hecal::contour {
namespace {

// I(x, y) = 3 + 2x − 5y is reproduced exactly by bilinear interpolation.
GrayImage Plane(int width, int height) {
  GrayImage image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) image.at(x, y) = static_cast<float>(3 + 2 * x - 5 * y);
  }
  return image;
}

TEST(GrayImage, SizeAndRowMajorLayout) {
  GrayImage image(4, 3, 7.0f);
  EXPECT_EQ(image.width(), 4);
  EXPECT_EQ(image.height(), 3);
  ASSERT_EQ(image.pixels().size(), 12u);
  EXPECT_EQ(image.pixels()[5], 7.0f);
  image.at(1, 2) = 9.0f;
  EXPECT_EQ(image.pixels()[2 * 4 + 1], 9.0f);
  EXPECT_THROW(GrayImage(-1, 2), std::invalid_argument);
  EXPECT_TRUE(GrayImage().empty());
}

TEST(GrayImage, PixelCentresAreIntegerCoordinates) {
  const GrayImage image = Plane(5, 4);
  EXPECT_DOUBLE_EQ(image.Sample(2.0, 1.0), image.at(2, 1));
  EXPECT_DOUBLE_EQ(image.Sample(0.0, 0.0), 3.0);
  EXPECT_DOUBLE_EQ(image.Sample(4.0, 3.0), 3 + 8 - 15);
}

TEST(GrayImage, BilinearIsExactForAPlane) {
  const GrayImage image = Plane(6, 5);
  for (double y = 0.0; y <= 4.0; y += 0.37) {
    for (double x = 0.0; x <= 5.0; x += 0.29) {
      EXPECT_NEAR(image.Sample(x, y), 3 + 2 * x - 5 * y, 1e-5) << x << "," << y;
    }
  }
  // The last row and column (no right/bottom neighbour) are exact too.
  EXPECT_NEAR(image.Sample(5.0, 2.5), 3 + 10 - 12.5, 1e-5);
  EXPECT_NEAR(image.Sample(1.5, 4.0), 3 + 3 - 20, 1e-5);
}

TEST(GrayImage, BilinearMixesTheFourNeighbours) {
  GrayImage image(2, 2);
  image.at(0, 0) = 0.0f;
  image.at(1, 0) = 10.0f;
  image.at(0, 1) = 20.0f;
  image.at(1, 1) = 70.0f;
  // (1−fx)(1−fy)·0 + fx(1−fy)·10 + (1−fx)fy·20 + fx fy·70 at (0.25, 0.5)
  EXPECT_NEAR(image.Sample(0.25, 0.5), 0.25 * 0.5 * 10 + 0.75 * 0.5 * 20 + 0.25 * 0.5 * 70, 1e-9);
}

TEST(GrayImage, ContainsIsTheInterpolationBoxAndOutsideClamps) {
  const GrayImage image = Plane(5, 4);
  EXPECT_TRUE(image.Contains(0.0, 0.0));
  EXPECT_TRUE(image.Contains(4.0, 3.0));
  EXPECT_FALSE(image.Contains(-0.01, 1.0));
  EXPECT_FALSE(image.Contains(1.0, 3.01));
  EXPECT_FALSE(image.Contains(4.5, 1.0));
  EXPECT_DOUBLE_EQ(image.Sample(-3.0, 1.0), image.at(0, 1));
  EXPECT_DOUBLE_EQ(image.Sample(2.0, 9.0), image.at(2, 3));
}

TEST(GrayImage, SinglePixelImage) {
  const GrayImage image(1, 1, 4.0f);
  EXPECT_TRUE(image.Contains(0.0, 0.0));
  EXPECT_DOUBLE_EQ(image.Sample(0.3, -2.0), 4.0);
}

}  // namespace
}  // namespace hecal::contour
