// The result file of `hecal pose` (docs/pose-from-points.md, docs/cli.md): one camera pose
// T_camera_target from object points and their pixels, as JSON:
//   {"hecal_version", "method", "units": {"length", "angle": "rad"},
//    "T_camera_target": {"frame", "matrix" (4×4), "translation", "quaternion_wxyz",
//                        "rotation_vector"},
//    "reprojection_rms_px",
//    "covariance": {"matrix" (6×6), "parameterization": "right, (rx,ry,rz,tx,ty,tz)",
//                   "pixel_sigma", "pixel_sigma_source": "given"|"estimated"}   (refined only),
//    "points": [{"id", "residual_px": [du, dv]}, ...], "warnings": [...]}
// Lengths (translation, the matrix's last column, the covariance's translation rows and
// columns) in `unit`; the estimate holds metres. A point's id is its id string, or its 1-based
// position when the points have no ids. The covariance is written symmetrised.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hecal/io/units.h"
#include "hecal/pose/pose_method.h"

namespace hecal::report {

// `point_ids` has one entry per residual of `estimate` (nullopt: the point has no id).
std::string PoseResultJson(const pose::PoseEstimate& estimate,
                           const std::vector<std::optional<std::string>>& point_ids,
                           io::LengthUnit unit);

}  // namespace hecal::report
