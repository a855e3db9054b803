// What one image shows to be wrong in a target description, said at the first image that shows
// it, with the fix (docs/targets.md, "A description that does not match the print"). The image
// front end (image_set.h) refuses the set at the first image with a mismatch and detects no
// further images. Each case compares the description with what the image itself shows:
//   - a chessboard found inside a larger board: the checker pattern continues beyond the corners
//     found, or the corners are not neighbours (chessboard_extent.h);
//   - a chessboard not found whose size one corner off is found whole (chessboard_size_probe.h):
//     one count off, or squares counted instead of inner corners;
//   - a marker target (charuco, grids, single tags) with no point found, while the image shows
//     markers of another dictionary or family, or of the described one with none of the board's
//     ids (marker_probe.h);
//   - a marker grid (aruco_grid, apriltag_grid) whose markers do not lie where the described
//     cols × rows layout puts them but where rows × cols does: the least-squares homography from
//     the layout's marker corners to the pixels fits the transposed layout to at most 5 % of a
//     marker's side and 1/4 of the described layout's RMS, which misfits by 10 % of a side or more
//     (a correct grid fits to the detection noise and lens distortion, well under 5 %).
// Rows and cols swapped on a chessboard are no mismatch: OpenCV finds the board either way and
// the points are the same board in a target frame turned by a quarter turn (docs/targets.md).
#pragma once

#include <opencv2/core/mat.hpp>
#include <string>

#include "hecal/pose/target.h"
#include "hecal/vision/detection.h"

namespace hecal::vision {

struct TargetMismatch {
  std::string problem;  // what the image shows against the description; empty: nothing wrong
  std::string fix;      // the change to the target file
  bool found() const { return !problem.empty(); }
};

// `gray`: the 8-bit grey image `detection` (DetectTarget with `target`) was made from.
TargetMismatch FindTargetMismatch(const cv::Mat& gray, const pose::TargetSpec& target,
                                  const Detection& detection);

}  // namespace hecal::vision
