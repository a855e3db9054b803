// ETH Zurich ASL hand_eye_calibration pose streams (github.com/ethz-asl/hand_eye_calibration,
// the CSVs of its datasets) → robot and camera pose tables with time stamps.
//
// Each file: CSV without header, one pose per line `t, x, y, z, q_x, q_y, q_z, q_w` (seconds,
// metres, Hamilton quaternion in x, y, z, w order; the upstream README's "Formats" section, whose
// layout line "t, x, y, z, q_x, q_y, q_z, q_w" is accepted as an optional first line).
//   robot file  = poses_B_H: the hand H in the robot base B = T_base_gripper → as is
//   camera file = poses_W_E: the camera (eye) E in the target/world frame W = T_target_camera
//                 → INVERTED to T_camera_target
// Source: data/ethz-robot-arm/SOURCE.md (README "poses_B_H" / "poses_W_E", target_extractor.cc
// writes T_G_C). The two streams are NOT synchronised (robot 50 Hz, camera ~30 Hz, different
// lengths): rows keep their stamps and are not paired here; associate them by stamp before
// calibrating. Ids are "r<k>" (robot) and "c<k>" (camera), k the 0-based row, so that pairing by
// id can never silently match unrelated rows.
#pragma once

#include <string>
#include <string_view>

#include "hecal/io/import_types.h"

namespace hecal::io {

ImportedPoses ParseEthzStreams(std::string_view robot_text, const std::string& robot_source,
                               std::string_view camera_text, const std::string& camera_source);

}  // namespace hecal::io
