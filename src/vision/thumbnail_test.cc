#include "hecal/vision/thumbnail.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "hecal/core/error.h"

namespace hecal::vision {
namespace {

TEST(Thumbnail, LongerSideAtMostMaxSide) {
  const std::string jpeg = ThumbnailJpeg(HECAL_SOURCE_DIR "/data/rwhe-kuka2/images/im_01.png", 320);
  ASSERT_GT(jpeg.size(), 2u);
  EXPECT_EQ(static_cast<unsigned char>(jpeg[0]), 0xFF);  // JPEG start-of-image
  EXPECT_EQ(static_cast<unsigned char>(jpeg[1]), 0xD8);
  const cv::Mat image =
      cv::imdecode(std::vector<unsigned char>(jpeg.begin(), jpeg.end()), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(image.cols, 320);  // 1920 x 1200 → 320 x 200
  EXPECT_EQ(image.rows, 200);
  EXPECT_LT(jpeg.size(), 40'000u);
}

TEST(Thumbnail, MissingFileIsAnInputErrorNamingIt) {
  try {
    ThumbnailJpeg("/nonexistent/im_99.png", 320);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/im_99.png"), std::string::npos);
  }
}

}  // namespace
}  // namespace hecal::vision
