// Contour files (`hecal contour track --init`, `contour render --contour`, `contour study
// --contour`; docs/cli.md, docs/contour.md): the points of one closed planar contour, read by the
// point file reader (point_file.h): CSV, or whitespace-separated when the header has no comma,
// '#' comment lines, the header `x,y` (case-insensitive, an optional `id` column), one point per
// line, in order around the contour. The unit is the caller's (pixels in an image, the unit of Z0
// in the target plane); values are returned as written.
//
// Errors (hecal::InputError naming the file and line): those of point_file.h (an unreadable
// file, a wrong header, a value that is not a finite number, no point), and fewer than 4 points
// (a closed B-spline needs 4 control points, contour/bspline.h).
#pragma once

#include <Eigen/Core>
#include <string>

namespace hecal::io {

// The points of the contour file `path`, one per column, in file order.
Eigen::Matrix2Xd ReadContourFile(const std::string& path);

}  // namespace hecal::io
