// Test support for the contour tests: the camera of the paper's setting, shared by the pose tests.
#pragma once

#include "hecal/contour/affine_pose.h"

namespace hecal::contour {

// Focal length in px and initial distance Z0 in mm.
inline constexpr ContourCamera kCamera{6024.0, 5000.0};

}  // namespace hecal::contour
