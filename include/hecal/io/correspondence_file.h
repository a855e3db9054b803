// Point matches between the images of robot stations, for the target-free global method
// (docs/global.md, "Correspondence files").
//
// Format: CSV, '#' comment lines and blank lines skipped; the first other line is the header,
// columns in any order, case-insensitive:
//   first, second   the stations of the motion: a robot-file id when the robot file has an id
//                   column, else the robot file's 1-based row number
//   id              optional: the match's name (an integer, unique within its motion); default
//                   its 0-based position within the motion
//   and ONE of
//   u1, v1, u2, v2           pixels (origin at the centre of the top-left pixel, as OpenCV),
//                            undistorted through --intrinsics by the caller; or
//   x1, y1, z1, x2, y2, z2   bearings (rays in the camera frame: z forward, x right, y down;
//                            any length ≠ 0, normalised on reading).
// Index 1 is the image at `first`, index 2 the image at `second`. Rows of one (first, second)
// pair form one motion; motions keep the order in which they first appear.
// Errors: hecal::InputError(file, line, problem, fix) for an unreadable or empty file, a missing,
// unknown or duplicate column, both or neither coordinate group, a wrong field count, a value
// that is not a finite number, a zero bearing, first = second, a duplicate id in a motion.
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

namespace hecal::io {

struct CorrespondenceMotion {
  std::string first;  // station name as written
  std::string second;
  int line = 0;  // of its first row
  std::vector<int> ids;
  std::vector<Eigen::Vector3d> first_points;  // pixels (u, v, 1) or unit bearings
  std::vector<Eigen::Vector3d> second_points;
  std::vector<int> lines;
};

struct CorrespondenceFile {
  bool pixels = true;  // u/v columns; false: bearings
  std::vector<CorrespondenceMotion> motions;
};

CorrespondenceFile ReadCorrespondenceFile(const std::string& path);
CorrespondenceFile ParseCorrespondenceFile(std::string_view text, const std::string& source);

}  // namespace hecal::io
