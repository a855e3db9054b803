// The extent of a detected chessboard against rendered boards whose corners are known: a board
// detected with its true size has no squares beyond it (with a white margin, without one, on a
// dark background); a cols × rows patch of a larger board's projected corners finds the board's
// true size on each side; corners two squares apart are not neighbours.
#include "hecal/vision/chessboard_extent.h"

#include <gtest/gtest.h>

#include "hecal/vision/detection.h"
#include "testing/rendered_scene.h"

namespace hecal::vision {
namespace {

using testing::MakeRenderedScene;
using testing::RenderedSceneOptions;

// The projected corners (c, r) for c in [c0, c0 + cols), r in [r0, r0 + rows) of a board with
// `board_cols` columns, at stride `stride`: row-major, as a detection lists them.
std::vector<Eigen::Vector2d> Patch(const testing::StationImage& truth, int board_cols, int c0,
                                   int r0, int cols, int rows, int stride = 1) {
  std::vector<Eigen::Vector2d> pixels;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      pixels.push_back(
          truth.pixels[static_cast<std::size_t>((r0 + stride * r) * board_cols + c0 + stride * c)]);
    }
  }
  return pixels;
}

RenderedSceneOptions LargeBoard() {
  RenderedSceneOptions options;
  options.target = testing::Chessboard(14, 11, 0.02);
  options.views = {testing::FrontalView(options.target, 0.55, 15.0, -10.0, 5.0),
                   testing::FrontalView(options.target, 0.6, -20.0, 15.0, -8.0)};
  return options;
}

TEST(ChessboardExtent, ABoardOfTheDescribedSizeHasNothingBeyondIt) {
  for (const double margin : {1.0, 0.0}) {
    for (const double background : {128.0, 15.0, 240.0}) {
      RenderedSceneOptions options;
      options.rendering.margin = margin;
      options.rendering.background = background;
      const testing::RenderedScene scene = MakeRenderedScene(options);
      for (std::size_t i = 0; i < scene.images.size(); ++i) {
        SCOPED_TRACE("margin " + std::to_string(margin) + ", background " +
                     std::to_string(background) + ", view " + std::to_string(i));
        const ChessboardExtent extent =
            MeasureChessboardExtent(scene.images[i], 9, 6, Patch(scene.truth[i], 9, 0, 0, 9, 6));
        EXPECT_FALSE(extent.larger());
      }
    }
  }
}

TEST(ChessboardExtent, TheDetectedCornersOfABoardOfTheDescribedSizePass) {
  const testing::RenderedScene scene = MakeRenderedScene({});
  const Detection detection = DetectTarget(scene.images[0], scene.target);
  ASSERT_EQ(detection.status, DetectionStatus::kFound) << detection.message;
  std::vector<Eigen::Vector2d> pixels;
  for (const ImagePoint& p : detection.points) pixels.push_back(p.pixel);
  EXPECT_FALSE(MeasureChessboardExtent(scene.images[0], 9, 6, pixels).larger());
}

TEST(ChessboardExtent, APatchOfALargerBoardFindsTheBoardOnEverySide) {
  const testing::RenderedScene scene = MakeRenderedScene(LargeBoard());
  for (std::size_t i = 0; i < scene.images.size(); ++i) {
    SCOPED_TRACE("view " + std::to_string(i));
    // A 9 × 6 patch at column 3, row 2 of the 14 × 11 board: 3 columns before it, 2 after,
    // 2 rows before, 3 after.
    const ChessboardExtent extent =
        MeasureChessboardExtent(scene.images[i], 9, 6, Patch(scene.truth[i], 14, 3, 2, 9, 6));
    EXPECT_TRUE(extent.larger());
    EXPECT_FALSE(extent.not_neighbours);
    EXPECT_EQ(extent.before_x, 3);
    EXPECT_EQ(extent.after_x, 2);
    EXPECT_EQ(extent.before_y, 2);
    EXPECT_EQ(extent.after_y, 3);
    EXPECT_FALSE(extent.out_of_view);
    // One corner short along x: found on the side where it is missing.
    const ChessboardExtent one_short =
        MeasureChessboardExtent(scene.images[i], 13, 11, Patch(scene.truth[i], 14, 1, 0, 13, 11));
    EXPECT_EQ(one_short.before_x, 1);
    EXPECT_EQ(one_short.after_x + one_short.before_y + one_short.after_y, 0);
  }
}

TEST(ChessboardExtent, CornersTwoSquaresApartAreNotNeighbours) {
  const testing::RenderedScene scene = MakeRenderedScene(LargeBoard());
  for (std::size_t i = 0; i < scene.images.size(); ++i) {
    SCOPED_TRACE("view " + std::to_string(i));
    const ChessboardExtent extent = MeasureChessboardExtent(
        scene.images[i], 7, 5, Patch(scene.truth[i], 14, 0, 0, 7, 5, /*stride=*/2));
    EXPECT_TRUE(extent.not_neighbours);
    EXPECT_TRUE(extent.larger());
  }
}

// The whole chain on rendered images: DetectTarget told 9 × 6 on images of the 14 × 11 board
// finds 54 corners somewhere on it (findChessboardCornersSB takes a sheared lattice of the
// board's corners, steps of one square along one axis and of (2, 1) squares along the other), and
// the extent says the board is larger: the corners are not neighbours, or, when they are, the walk
// finds the rest of the 14 × 11 board.
TEST(ChessboardExtent, TheDetectorsPatchOfALargerBoardIsFoundLarger) {
  const testing::RenderedScene scene = MakeRenderedScene(LargeBoard());
  const pose::TargetSpec described = testing::Chessboard(9, 6, 0.02);
  for (std::size_t i = 0; i < scene.images.size(); ++i) {
    SCOPED_TRACE("view " + std::to_string(i));
    const Detection detection = DetectTarget(scene.images[i], described);
    ASSERT_EQ(detection.num_points(), 54) << detection.message;
    std::vector<Eigen::Vector2d> pixels;
    for (const ImagePoint& p : detection.points) pixels.push_back(p.pixel);
    const ChessboardExtent extent = MeasureChessboardExtent(scene.images[i], 9, 6, pixels);
    EXPECT_TRUE(extent.larger());
    if (!extent.not_neighbours) {
      const int cols = 9 + extent.before_x + extent.after_x;
      const int rows = 6 + extent.before_y + extent.after_y;
      EXPECT_TRUE((cols == 14 && rows == 11) || (cols == 11 && rows == 14)) << cols << "x" << rows;
    }
  }
}

TEST(ChessboardExtent, TooFewCornersGiveNoExtent) {
  const testing::RenderedScene scene = MakeRenderedScene(LargeBoard());
  EXPECT_FALSE(MeasureChessboardExtent(scene.images[0], 2, 6, Patch(scene.truth[0], 14, 3, 2, 2, 6))
                   .larger());
  EXPECT_FALSE(MeasureChessboardExtent(scene.images[0], 9, 6, {}).larger());
}

}  // namespace
}  // namespace hecal::vision
