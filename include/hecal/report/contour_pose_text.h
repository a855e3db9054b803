// The camera motion of one shape vector as readable text (what `hecal contour pose` prints
// without --json; docs/cli.md#hecal-contour-pose), beside its JSON (contour_pose_file.h).
//
// Lines, to 9 significant digits: the translation (Tx, Ty, Tz) in the unit of Z0; the rotation
// matrix, a row per line; the Euler angles of the pose's rotation form (ZYX or ZXZ) in radians and
// in degrees. With the UT (contour/pose_uncertainty.h): the 1σ of each parameter
// (PoseParameterNames: the translation in the unit of Z0, the angles in degrees), "(biased)" where
// the bias check flags it, and a line explaining the bias when any is flagged.
#pragma once

#include <ostream>

#include "hecal/contour/shape_pose.h"

namespace hecal::report {

void PrintContourPose(std::ostream& out, const contour::ShapePose& result);

}  // namespace hecal::report
