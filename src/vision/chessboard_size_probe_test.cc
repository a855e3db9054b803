// The size probe against boards of known size: a rendered 9 × 6 board described one corner off
// in either count is found as 9 × 6; a 9 × 6 board cut by the image border (its last row of corners
// out of view, the described size correct) is not taken for a 9 × 5 one, nor does its true size
// give anything; the real 24 × 17 board of data/rwhe-kuka2 described as 23 × 17 and 25 × 18
// (squares counted) is found as 24 × 17.
#include "hecal/vision/chessboard_size_probe.h"

#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>

#include "testing/kuka2_views.h"
#include "testing/rendered_scene.h"

namespace hecal::vision {
namespace {

using testing::MakeRenderedScene;
using testing::RenderedSceneOptions;

std::string Text(const std::optional<cv::Size>& size) {
  return size ? std::to_string(size->width) + "x" + std::to_string(size->height) : "nothing";
}

TEST(ChessboardSizeProbe, FindsTheRenderedBoardOneCornerOff) {
  RenderedSceneOptions options;
  options.views.resize(1);
  const cv::Mat image = MakeRenderedScene(options).images[0];
  EXPECT_EQ(Text(ProbeChessboardSize(image, 8, 6)), "9x6");
  EXPECT_EQ(Text(ProbeChessboardSize(image, 10, 6)), "9x6");
  EXPECT_EQ(Text(ProbeChessboardSize(image, 9, 5)), "9x6");
}

TEST(ChessboardSizeProbe, ABoardCutByTheBorderIsNotASmallerBoard) {
  RenderedSceneOptions options;
  // Frontal at 0.4 m (25 mm squares: about 39 px), the centre moved down by 102 mm so that the
  // last row of corners lies just beyond the bottom of the 480 px image.
  const Pose frontal = testing::FrontalView(options.target, 0.4, 0.0, 0.0, 0.0);
  options.views = {
      MakePose(frontal.linear(), frontal.translation() + Eigen::Vector3d(0, 0.102, 0))};
  const testing::RenderedScene scene = MakeRenderedScene(options);
  const testing::StationImage& truth = scene.truth[0];
  ASSERT_GT(truth.pixels.back().y(), 480.0);  // the last row (ids 45..53) out of view
  ASSERT_LT(truth.pixels[36].y(), 470.0);     // the one before it in view
  // The classic detector does find the 9 x 5 corners in view; the probe must not offer them.
  std::vector<cv::Point2f> corners;
  EXPECT_TRUE(
      cv::findChessboardCorners(scene.images[0], cv::Size(9, 5), corners,
                                cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE));
  EXPECT_EQ(Text(ProbeChessboardSize(scene.images[0], 9, 6)), "nothing");
}

TEST(ChessboardSizeProbe, FindsTheKuka2Board) {
  const cv::Mat image = cv::imread(kuka2::Directory() + "images/im_01.png", cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(Text(ProbeChessboardSize(image, 23, 17)), "24x17");
  EXPECT_EQ(Text(ProbeChessboardSize(image, 25, 18)), "24x17");
}

}  // namespace
}  // namespace hecal::vision
