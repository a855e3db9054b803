// Which chessboard do the images show when the described one is not found? The commonest
// mistakes in a chessboard description are one count off by one (an inner corner miscounted) and
// both counts one too many (squares counted instead of inner corners: a board of 25 × 18 squares
// has 24 × 17 inner corners). A description one off is found by neither OpenCV detector on the
// printed board (measured on data/rwhe-kuka2, 24 × 17, described as 23 × 17, 24 × 16 or 25 × 18:
// found in none of the images after 4.6 s of findChessboardCornersSB each), so the set was refused
// as "found in none of the images" only after every image had been searched, without saying
// which size the print has.
//
// Method: cv::findChessboardCorners (the classic detector: it succeeds only when it finds
// exactly the size asked for, and fails fast otherwise) with the sizes one inner corner off the
// description, nearest first: (cols ± 1, rows), (cols, rows ± 1), then (cols − 1, rows − 1) and
// (cols + 1, rows + 1) (a failed search costs about 1 s on a 640 × 480 image of a board, so the
// unlikely (cols ± 1, rows ∓ 1) are not tried), on
// the image scaled down (INTER_AREA) to at most 1000 px along its longer side (a failed search
// of a 1920 × 1200 image takes about 2 s at full size).
// Rows and cols swapped need no probe: OpenCV finds a chessboard either way (docs/targets.md).
// A size found counts only when the board it gives is whole in the image and alone: its corners
// lie at least kBorderSquares (1.5) square sides from the image border (so that a board of the
// described size cut by the border, one line of corners out of view, is not taken for a smaller
// board), and the checker pattern does not continue beyond them (chessboard_extent.h).
//
// Input: the grey image and the described inner-corner counts. Output: the size found, or
// nullopt.
#pragma once

#include <opencv2/core/mat.hpp>
#include <optional>

namespace hecal::vision {

inline constexpr double kBorderSquares = 1.5;

std::optional<cv::Size> ProbeChessboardSize(const cv::Mat& gray, int cols, int rows);

}  // namespace hecal::vision
