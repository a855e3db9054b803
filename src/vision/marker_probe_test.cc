// The marker probe against markers of known kind: the ChArUco photo of data/moveit-calibration
// (17 DICT_5X5_250 markers, ids 0 to 16, SOURCE.md), a rendered tag36h11 grid (ids 3 to 22), a
// rendered chessboard (no markers); and the names it gives (kind, smallest dictionary).
#include "hecal/vision/marker_probe.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "testing/moveit_photos.h"
#include "testing/rendered_scene.h"

namespace hecal::vision {
namespace {

TEST(MarkerProbe, FindsTheKindAndTheIds) {
  const cv::Mat photo = cv::imread(
      hecal::testing::MoveItPhotoPath("test_charuco_board_detection.jpg"), cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(photo.empty());
  const std::optional<MarkersSeen> charuco = ProbeMarkers(photo, 2);
  ASSERT_TRUE(charuco.has_value());
  EXPECT_EQ(charuco->dictionary, "DICT_5X5_1000");
  EXPECT_EQ(charuco->Kind(), "DICT_5X5 markers");
  EXPECT_EQ(charuco->Smallest(), "DICT_5X5_50");
  EXPECT_EQ(charuco->count, 17);
  EXPECT_EQ(charuco->min_id, 0);
  EXPECT_EQ(charuco->max_id, 16);
  EXPECT_FALSE(ProbeMarkers(photo, 18).has_value());

  hecal::testing::RenderedSceneOptions options;
  options.target = hecal::testing::AprilTagGrid();
  options.views = {hecal::testing::FrontalView(options.target, 0.5, 15.0, -10.0, 5.0)};
  const std::optional<MarkersSeen> april = ProbeMarkers(MakeRenderedScene(options).images[0], 2);
  ASSERT_TRUE(april.has_value());
  EXPECT_EQ(april->Kind(), "tag36h11 AprilTags");
  EXPECT_EQ(april->Smallest(), "tag36h11");
  EXPECT_EQ(april->count, 20);
  EXPECT_EQ(april->min_id, 3);
  EXPECT_EQ(april->max_id, 22);

  options.target = hecal::testing::Board();
  options.views.resize(1);
  EXPECT_FALSE(ProbeMarkers(MakeRenderedScene(options).images[0], 1).has_value());
}

TEST(MarkerProbe, SmallestDictionaryHoldsEveryId) {
  MarkersSeen seen{"DICT_4X4_1000", "", 3, 0, 49};
  EXPECT_EQ(seen.Smallest(), "DICT_4X4_50");
  seen.max_id = 50;
  EXPECT_EQ(seen.Smallest(), "DICT_4X4_100");
  seen.max_id = 999;
  EXPECT_EQ(seen.Smallest(), "DICT_4X4_1000");
  seen.dictionary = "DICT_ARUCO_ORIGINAL";
  EXPECT_EQ(seen.Kind(), "DICT_ARUCO_ORIGINAL markers");
  EXPECT_EQ(seen.Smallest(), "DICT_ARUCO_ORIGINAL");
}

}  // namespace
}  // namespace hecal::vision
