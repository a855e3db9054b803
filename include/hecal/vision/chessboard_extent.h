// Does a detected chessboard continue beyond the corners the target file describes? When
// cols × rows is smaller than the printed board (a 9×6 for a 24×17 board, or one corner short),
// cv::findChessboardCorners and findChessboardCornersSB lock onto some cols × rows patch of it,
// a different patch in each image, so the target frame jumps across the board from image to
// image and no calibration can fit the points (docs/targets.md, "When the description does not
// match the print"). A board of the described size is surrounded by its margin or background,
// never by more squares of the same checker pattern, so squares beyond the detection are proof
// that the board is larger.
//
// Method: a walk outward from each of the four sides of the detected grid of inner corners. At
// each step a homography from grid to pixel coordinates is fitted to the three outermost known
// corner lines of that side (local, so lens distortion bends the prediction little), and the
// next ring of squares beyond them is predicted (its centres half a square beyond the next corner
// line). The board's own border squares (half a square outside the outermost inner corners)
// always exist; every ring beyond them means one more line of inner corners. A ring counts when
// at least 3 of its squares lie in the image and at least 80% of those take the colour the
// checker parity predicts (each square's mean grey level in a disc of 0.2 × its side, judged
// against the mean dark and bright levels of the detected board's inner squares; a margin, all
// bright, matches only half of them). The new corner line is then located with cv::cornerSubPix
// and joins the fit, and the walk goes on until a ring fails or leaves the image.
//
// Corners that are not neighbours: the squares between the detected corners must alternate
// between dark and bright, with the contrast of the print. Each square's mean grey level (the
// disc above, at the mean of its 4 corners) is judged against the mean level of its parity and of
// the other; the contrast is the difference of the two parities' means over the grey-level
// spread (5th to 95th percentile) in the corners' bounding box. A checker pattern of
// neighbouring corners has 80% and more of its squares nearer their parity's mean and a contrast
// of 0.5 and more (data/rwhe-kuka2 24×17: 100% and 0.90–0.97 on all 28 images); fewer than 65%,
// or a contrast below 0.25, mean that the detector has taken corners of a larger board that are
// not neighbours: then each "square" straddles several squares of the print and is grey. On
// data/rwhe-kuka2 described as 9×6, findChessboardCornersSB returns a sheared lattice of the
// board's corners (contrast 0.003); on a rendered 14×11 board described as 9×6, corners one
// square apart along one axis and (2, 1) squares apart along the other. Then no walk is made
// (not_neighbours). Between the two thresholds nothing is said (no walk, not larger).
//
// Input: the grey image and the detection's corners of a cols × rows chessboard, row-major
// (id = r·cols + c, pose/target.h). Output: the number of further inner-corner lines found
// beyond each side, and whether a side's walk stopped at the image border (the board may extend
// further out of view: "at least").
#pragma once

#include <Eigen/Core>
#include <limits>
#include <opencv2/core/mat.hpp>
#include <vector>

namespace hecal::vision {

struct ChessboardExtent {
  // The checker pattern at the detected corners (NaN when a parity has no square in the image):
  // the fraction of the inner squares nearer their parity's mean grey level than the other's, and
  // the difference of the two means over the grey-level spread (5th to 95th percentile) in the
  // corners' bounding box.
  double alternation = std::numeric_limits<double>::quiet_NaN();
  double contrast = std::numeric_limits<double>::quiet_NaN();
  bool not_neighbours = false;  // the squares between the corners do not alternate (below)
  int before_x = 0;             // further inner-corner columns before column 0 (towards −x)
  int after_x = 0;              // after column cols − 1
  int before_y = 0;             // further inner-corner rows before row 0 (towards −y)
  int after_y = 0;              // after row rows − 1
  bool out_of_view = false;     // a walk that found more squares stopped at the image border

  bool larger() const { return not_neighbours || before_x + after_x + before_y + after_y > 0; }
};

// `corners`: cols·rows pixels, row-major. Fewer corners, or cols or rows below 3, give an empty
// extent (nothing to extrapolate from).
ChessboardExtent MeasureChessboardExtent(const cv::Mat& gray, int cols, int rows,
                                         const std::vector<Eigen::Vector2d>& corners);

}  // namespace hecal::vision
