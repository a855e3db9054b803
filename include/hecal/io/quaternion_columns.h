// Whether a pose table's rotations were quaternion columns (qw, qx, qy, qz; docs/pose-files.md).
// Their order is the one column layout a user can mislabel without the reader noticing (a
// quaternion read one place off is still a unit quaternion), so the convention check
// (handeye/convention_check.h, PoseData::robot_quaternions) also tries that order when this is
// true. False for rotation matrices, rotation vectors, Euler angles and matrix lines.
#pragma once

#include "hecal/io/pose_table.h"

namespace hecal::io {

bool HasQuaternionColumns(const PoseTable& table);

}  // namespace hecal::io
