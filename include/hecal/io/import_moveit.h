// MoveIt Calibration pose samples (moveit_calibration's handeye solver test data,
// pose_samples.json) → robot and camera pose tables.
//
// Format: a JSON array of samples; each sample is [M_eef, M_obj], each M a 4×4 homogeneous matrix
// given as 4 row arrays (row-major, last row [0, 0, 0, 1]), metres.
//   sample[i][0] = eef_wrt_world  = T_base_eef    → robot row as is (no inverse)
//   sample[i][1] = obj_wrt_sensor = T_camera_target → camera row as is (no inverse)
// Source of the convention: data/moveit-calibration/SOURCE.md (handeye_solver_test.cpp reads
// root[i][0] into eef_wrt_world and root[i][1] into obj_wrt_sensor; crigroup/handeye documents
// them as the end-effector w.r.t. the robot base and the pattern w.r.t. the camera).
// Ids are the 0-based sample index. JSON numbers carry no printed precision, so the rotation
// tolerance (rotation_input.h) is 1e-3, not widened by the digits.
#pragma once

#include <string>
#include <string_view>

#include "hecal/io/import_types.h"

namespace hecal::io {

// Throws hecal::InputError (source, line of a JSON syntax error, what, how to fix) on bad input.
ImportedPoses ParseMoveitSamples(std::string_view json_text, const std::string& source);

}  // namespace hecal::io
