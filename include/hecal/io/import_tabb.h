// Tabb & Ahmad Yousef robot-world-hand-eye data (robot_cali.txt + cali.txt, as redistributed in
// opencv_extra testdata) → robot and camera pose tables (+ the camera intrinsics).
//
// robot_cali.txt: first line N, then N 4×4 homogeneous matrices, 4 text rows each (row-major),
//   blank lines between, millimetres. They are B_i = T_gripper_base (the pose of the robot base
//   in the gripper frame — "our definition is the inverse of some other works", Tabb's README;
//   OpenCV's test reads them as R_base2gripper) → INVERTED to T_base_gripper.
// cali.txt: first line N, then one line per image with 30 fields
//   `imageK.png fx 0 cx 0 fy cy 0 0 1 r11 .. r33 tx ty tz k1 k2 p1 p2 k3 0 0 0`:
//   the chessboard pose in the camera frame T_camera_target (R row-major, t in millimetres) → as
//   is; K and the plumb_bob distortion are the intrinsics.
// Source: data/tabb-rwhe-dataset1/SOURCE.md. Line i of cali.txt pairs with block i of
// robot_cali.txt (as OpenCV's loader does); both rows get the image's file stem ("image0") as id.
// Lengths stay in millimetres (the CSV is written with x_mm,y_mm,z_mm columns).
// Both counts must equal their N and each other.
#pragma once

#include <string>
#include <string_view>

#include "hecal/io/import_types.h"

namespace hecal::io {

ImportedPoses ParseTabb(std::string_view robot_text, const std::string& robot_source,
                        std::string_view camera_text, const std::string& camera_source);

}  // namespace hecal::io
