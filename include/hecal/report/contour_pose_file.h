// The JSON of `hecal contour pose --json` (docs/contour.md, docs/cli.md): the camera motion of
// one shape vector (contour/shape_pose.h),
//   {"translation" (unit of Z0), "rotation_matrix" (3×3), "euler" (rad), "euler_deg",
//    "sequence" ("ZYX" | "ZXZ"), "units": {"translation", "euler", "euler_deg"}}
// and, with the UT: "parameters" (the six names, PoseParameterNames), "ut_mean", "covariance"
// (6×6 over the parameters: the unit of Z0 and rad) and "bias" ({name: bool}, the bias check of
// contour/pose_uncertainty.h).
#pragma once

#include <string>

#include "hecal/contour/shape_pose.h"

namespace hecal::report {

// The document, pretty-printed (two-space indent) with a final newline.
std::string ContourPoseJson(const contour::ShapePose& result);

}  // namespace hecal::report
