// The camera pose from points as readable text (what `hecal pose` prints;
// docs/pose-from-points.md), beside its JSON (pose_file.h): the method and point count;
// T_camera_target as a 3×4 matrix [R | t] with t in `unit`, t again, and the rotation vector
// (radians, and its angle in degrees); for refined methods the 1σ of the rotation (degrees) and
// translation (`unit`) per component (right perturbation); the reprojection RMS per point (px) with
// the pixel σ and whether it was given or estimated, or that the method is not refined (no
// covariance). The estimate holds metres.
#pragma once

#include <cstddef>
#include <ostream>

#include "hecal/io/units.h"
#include "hecal/pose/pose_method.h"

namespace hecal::report {

// `points`: how many point pairs the pose was estimated from.
void PrintPoseEstimate(std::ostream& out, const pose::PoseEstimate& estimate, std::size_t points,
                       io::LengthUnit unit);

}  // namespace hecal::report
