// Real images (data/rwhe-kuka2, testing/kuka2_views.h: a 24 × 17 inner-corner board filling
// much of 1920 × 1200 images): with its true size the board has nothing beyond it and its
// squares alternate with full contrast in the first and the last view (measured on all 28:
// alternation 1.000, contrast 0.90–0.97); described as 9 × 6 (the reproduction of
// docs/targets.md, "A description that does not match the print") the corners
// findChessboardCornersSB returns on the first view are not neighbours (alternation 0.55,
// contrast 0.003).
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "hecal/vision/chessboard_extent.h"
#include "hecal/vision/image_set.h"
#include "testing/kuka2_views.h"

namespace hecal::vision {
namespace {

cv::Mat Image(int number) {
  const std::string name = kuka2::Directory() + "images/im_" + (number < 10 ? "0" : "") +
                           std::to_string(number) + ".png";
  return cv::imread(name, cv::IMREAD_GRAYSCALE);
}

TEST(ChessboardExtentKuka2, TheTrueBoardHasNothingBeyondIt) {
  for (const int number : {1, 28}) {
    SCOPED_TRACE("im_" + std::to_string(number));
    const cv::Mat image = Image(number);
    ASSERT_FALSE(image.empty());
    const Detection detection = DetectTarget(image, kuka2::Target());
    ASSERT_EQ(detection.status, DetectionStatus::kFound) << detection.message;
    const ChessboardExtent extent = MeasureChessboardExtent(image, 24, 17, PixelsOf(detection));
    EXPECT_FALSE(extent.larger());
    EXPECT_GT(extent.alternation, 0.95);
    EXPECT_GT(extent.contrast, 0.7);
  }
}

TEST(ChessboardExtentKuka2, NineBySixCornersAreNotNeighbours) {
  const cv::Mat image = Image(1);
  ASSERT_FALSE(image.empty());
  const Detection detection = DetectTarget(image, hecal::testing::Chessboard(9, 6, 0.015));
  ASSERT_EQ(detection.num_points(), 54) << detection.message;
  const ChessboardExtent extent = MeasureChessboardExtent(image, 9, 6, PixelsOf(detection));
  EXPECT_TRUE(extent.not_neighbours);
  EXPECT_LT(extent.contrast, 0.25);
}

}  // namespace
}  // namespace hecal::vision
